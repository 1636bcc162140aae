package org.triad.building.traffic;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.triad.building.traffic.Resource.Kind;

/**
 * The building's map as traffic control sees it: nodes (spots a robot stands on), edges (the lanes between
 * two nodes, usable both ways) and areas (a narrow corridor, a doorway, the lift cabin) over several nodes
 * and edges, each a {@link Resource} with a capacity. A node inside no area (zones aside) is a <em>stop node</em>: the
 * only kind of node where a robot may wait (halls, rooms, the spot before a door); a robot never waits
 * inside a corridor, a doorway or the lift. Built once from the application's floor map:
 *
 * <pre>{@code
 * TrafficMap map = TrafficMap.builder()
 *         .node("hall-w", 2).node("c1").node("c2").node("hall-e", 2)
 *         .edge("hall-w", "c1").edge("c1", "c2").edge("c2", "hall-e")
 *         .area(Kind.CORRIDOR, "west", 1, "c1", "c2", "hall-w-c1", "c1-c2", "c2-hall-e")
 *         .build();                                   // TrafficMapException listing every problem
 * }</pre>
 */
public final class TrafficMap {
    private final Map<String, Resource> nodes;
    private final Map<String, Resource> edges;
    private final Map<String, Resource> areas;
    /** "a b" and "b a" to the edge between them. */
    private final Map<String, Resource> edgeByEnds;
    private final Map<String, List<String>> edgeEnds;
    private final Map<String, Set<String>> neighbours;
    /** node or edge id to the areas that contain it. */
    private final Map<Resource, List<Resource>> areasOf;
    /** Edge id to its length in metres, where the floor map gave one. */
    private final Map<String, Double> lengths;

    private TrafficMap(Builder b) {
        this.nodes = Collections.unmodifiableMap(b.nodes);
        this.edges = Collections.unmodifiableMap(b.edges);
        this.areas = Collections.unmodifiableMap(b.areas);
        this.edgeByEnds = new LinkedHashMap<>();
        this.edgeEnds = new LinkedHashMap<>();
        this.neighbours = new LinkedHashMap<>();
        this.areasOf = new LinkedHashMap<>();
        this.lengths = Map.copyOf(b.lengths);
        nodes.keySet().forEach(n -> neighbours.put(n, new LinkedHashSet<>()));
        b.edgeEnds.forEach((id, ends) -> {
            Resource e = edges.get(id);
            edgeEnds.put(id, ends);
            edgeByEnds.put(ends.get(0) + " " + ends.get(1), e);
            edgeByEnds.put(ends.get(1) + " " + ends.get(0), e);
            neighbours.get(ends.get(0)).add(ends.get(1));
            neighbours.get(ends.get(1)).add(ends.get(0));
        });
        b.areaMembers.forEach((areaId, members) -> {
            Resource area = areas.get(areaId);
            for (String m : members) {
                Resource r = nodes.containsKey(m) ? nodes.get(m) : edges.get(m);
                areasOf.computeIfAbsent(r, k -> new ArrayList<>()).add(area);
            }
        });
    }

    public static Builder builder() {
        return new Builder();
    }

    /** The node resource with this id. */
    public Resource node(String id) {
        Resource r = nodes.get(id);
        if (r == null) {
            throw new IllegalArgumentException("node '" + id + "' is not on the traffic map");
        }
        return r;
    }

    public Set<String> nodeIds() {
        return nodes.keySet();
    }

    public boolean hasNode(String id) {
        return nodes.containsKey(id);
    }

    /** The edge between two nodes (either way round), if any. */
    public Optional<Resource> edge(String a, String b) {
        return Optional.ofNullable(edgeByEnds.get(a + " " + b));
    }

    /** The nodes joined to this one by an edge. */
    public Set<String> neighbours(String node) {
        node(node);
        return Collections.unmodifiableSet(neighbours.get(node));
    }

    public Optional<Resource> area(String id) {
        return Optional.ofNullable(areas.get(id));
    }

    /**
     * The length of the edge between two neighbouring nodes, metres (what a robot drives on it), if the floor map gave one.
     *
     * @throws IllegalArgumentException when the two are not joined by an edge
     */
    public java.util.OptionalDouble length(String a, String b) {
        Resource e = edge(a, b).orElseThrow(() -> new IllegalArgumentException("no edge joins node '" + a + "' and node '" + b + "' on the traffic map"));
        Double m = lengths.get(e.id());
        return m == null ? java.util.OptionalDouble.empty() : java.util.OptionalDouble.of(m);
    }

    /** Every resource of the map: nodes, edges, areas. */
    public List<Resource> resources() {
        List<Resource> all = new ArrayList<>(nodes.values());
        all.addAll(edges.values());
        all.addAll(areas.values());
        return all;
    }

    /** The areas containing this node or edge. */
    public List<Resource> areasOf(Resource nodeOrEdge) {
        return areasOf.getOrDefault(nodeOrEdge, List.of());
    }

    /** Whether a robot may wait at this node: it lies in no area but zones (a zone is a region robots are admitted to, a floor). */
    public boolean isStop(String node) {
        return areasOf(node(node)).stream().allMatch(a -> a.kind() == Kind.ZONE);
    }

    /** What a robot standing at this node occupies: the node and the areas containing it. */
    public Set<Resource> standing(String node) {
        Set<Resource> s = new LinkedHashSet<>();
        s.add(node(node));
        s.addAll(areasOf(node(node)));
        return s;
    }

    /**
     * What a robot occupies driving from {@code from} to its neighbour {@code to}: the edge, the node
     * {@code to} and every area containing either.
     *
     * @throws IllegalArgumentException when the two are not joined by an edge
     */
    public Set<Resource> step(String from, String to) {
        Resource e = edge(from, to).orElseThrow(() -> new IllegalArgumentException(
                "no edge joins node '" + from + "' and node '" + to + "' on the traffic map"));
        Set<Resource> s = new LinkedHashSet<>();
        s.add(e);
        s.addAll(areasOf(e));
        s.addAll(standing(to));
        return s;
    }

    /** Builds a map; {@link #build()} checks it whole and reports every problem at once. */
    public static final class Builder {
        private final Map<String, Resource> nodes = new LinkedHashMap<>();
        private final Map<String, Resource> edges = new LinkedHashMap<>();
        private final Map<String, Resource> areas = new LinkedHashMap<>();
        private final Map<String, List<String>> edgeEnds = new LinkedHashMap<>();
        private final Map<String, List<String>> areaMembers = new LinkedHashMap<>();
        private final Map<String, Double> lengths = new LinkedHashMap<>();
        private final List<String> problems = new ArrayList<>();

        private Builder() {
        }

        /** A node one robot fits on. */
        public Builder node(String id) {
            return node(id, 1);
        }

        /** A node {@code capacity} robots fit on at once (a hall where robots pass each other). */
        public Builder node(String id, int capacity) {
            if (nodes.containsKey(id) || edges.containsKey(id)) {
                problems.add("node '" + id + "' is declared twice (or an edge has that id)");
            }
            nodes.put(id, new Resource(Kind.NODE, id, checked("node '" + id + "'", capacity)));
            return this;
        }

        /** A single lane between nodes {@code a} and {@code b}, named {@code a-b}. */
        public Builder edge(String a, String b) {
            return edge(a + "-" + b, a, b, 1);
        }

        /** An edge between nodes {@code a} and {@code b}, usable both ways, {@code capacity} robots at once. */
        public Builder edge(String id, String a, String b, int capacity) {
            if (edges.containsKey(id) || nodes.containsKey(id)) {
                problems.add("edge '" + id + "' is declared twice (or a node has that id)");
            }
            if (a.equals(b)) {
                problems.add("edge '" + id + "' joins node '" + a + "' to itself");
            }
            for (List<String> ends : edgeEnds.values()) {
                if (ends.contains(a) && ends.contains(b) && !a.equals(b)) {
                    problems.add("edge '" + id + "' joins nodes '" + a + "' and '" + b + "', already joined by another edge");
                }
            }
            edges.put(id, new Resource(Kind.EDGE, id, checked("edge '" + id + "'", capacity)));
            edgeEnds.put(id, List.of(a, b));
            return this;
        }

        /**
         * An area of this kind over these nodes and edges (by id), {@code capacity} robots at once: a narrow
         * corridor, a doorway, the lift cabin (its nodes on every floor and the ride between them).
         */
        public Builder area(Kind kind, String id, int capacity, String... members) {
            if (!kind.isArea()) {
                problems.add("area '" + id + "' has kind " + kind + "; an area is a corridor, door, lift or zone");
            }
            if (areas.containsKey(id)) {
                problems.add(kind.label() + " '" + id + "' is declared twice");
            }
            if (members.length == 0) {
                problems.add(kind.label() + " '" + id + "' covers no node or edge");
            }
            areas.put(id, new Resource(kind, id, checked(kind.label() + " '" + id + "'", capacity)));
            areaMembers.put(id, List.of(members));
            return this;
        }

        /** The length of the edge {@code id} in metres (what a robot drives on it: a charge's reserve counts it). */
        public Builder length(String id, double metres) {
            if (!(metres >= 0) || Double.isInfinite(metres)) {
                problems.add("edge '" + id + "' has length " + metres + "; a length is a finite number of metres >= 0");
            }
            lengths.put(id, metres);
            return this;
        }

        /** The node ids declared so far (to name an area's members). */
        public java.util.Set<String> nodeIds() {
            return Collections.unmodifiableSet(nodes.keySet());
        }

        /** The edge ids declared so far. */
        public java.util.Set<String> edgeIds() {
            return Collections.unmodifiableSet(edges.keySet());
        }

        private int checked(String what, int capacity) {
            if (capacity < 1) {
                problems.add(what + " has capacity " + capacity + "; a capacity is at least 1 robot");
                return 1;
            }
            return capacity;
        }

        /** @throws TrafficMapException naming every edge whose node does not exist, every capacity below 1, ... */
        public TrafficMap build() {
            List<String> all = new ArrayList<>(problems);
            edgeEnds.forEach((id, ends) -> {
                for (String n : ends) {
                    if (!nodes.containsKey(n)) {
                        all.add("edge '" + id + "' joins node '" + n + "', which is not on the map");
                    }
                }
            });
            areaMembers.forEach((id, members) -> {
                for (String m : members) {
                    if (!nodes.containsKey(m) && !edges.containsKey(m)) {
                        all.add(areas.get(id) + " covers '" + m + "', which is neither a node nor an edge of the map");
                    }
                }
            });
            lengths.keySet().stream().filter(id -> !edges.containsKey(id))
                    .forEach(id -> all.add("a length is given for edge '" + id + "', which is not an edge of the map"));
            if (nodes.isEmpty()) {
                all.add("the map has no node");
            }
            if (!all.isEmpty()) {
                throw new TrafficMapException(all);
            }
            return new TrafficMap(this);
        }
    }
}
