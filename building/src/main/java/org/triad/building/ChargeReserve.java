package org.triad.building;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.OptionalDouble;
import java.util.PriorityQueue;
import java.util.function.BiFunction;

import org.triad.building.traffic.TrafficMap;

/**
 * When a robot that drains its battery by the metre goes to charge, measured on the building's traffic map: it takes
 * its next leg only if its charge covers the leg, then the way from the leg's end back to the dock, then a margin for
 * what it drives beyond the map's lanes (see {@link #ChargeReserve}); otherwise it drives to the dock first. A fixed
 * threshold (the building benchmark's 60 %) knew neither how long the leg was nor how far the dock: a courier could
 * leave at 61 % for the farthest ward and come back through a crowded single lane with nothing in hand.
 */
public final class ChargeReserve {
    private final TrafficMap map;
    private final String dock;
    private final double drainPercentPerMetre;
    private final double marginPercent;
    private final BiFunction<String, String, List<String>> routes;

    /**
     * @param drainPercentPerMetre what a metre driven takes of a full battery, percent
     * @param marginPercent        kept in hand beyond the leg and the way back, percent: what the robot drives that the
     *                             map's lanes do not say (stepping aside for another robot and back, backing off a blocked
     *                             lane); the caller says what it covers, as it knows its robots. Waiting costs nothing here:
     *                             the battery drains by the metre
     * @param routes               the route the robot drives between two nodes (the dock's way back is what it will drive),
     *                             or null for the shortest by metres on the map
     * @throws IllegalArgumentException for a dock not on the map, a negative drain or margin, or an edge without a length
     */
    public ChargeReserve(TrafficMap map, String dock, double drainPercentPerMetre, double marginPercent, BiFunction<String, String, List<String>> routes) {
        this.map = Objects.requireNonNull(map, "map");
        this.dock = Objects.requireNonNull(dock, "dock");
        map.node(dock);
        if (!(drainPercentPerMetre > 0) || !(marginPercent >= 0) || Double.isInfinite(drainPercentPerMetre) || Double.isInfinite(marginPercent)) {
            throw new IllegalArgumentException("a drain is a positive percent per metre and a margin a percent >= 0, not " + drainPercentPerMetre + " and "
                    + marginPercent);
        }
        for (String a : map.nodeIds()) {
            for (String b : map.neighbours(a)) {
                if (map.length(a, b).isEmpty()) {
                    throw new IllegalArgumentException("the traffic map gives no length for the edge between '" + a + "' and '" + b
                            + "': a charge's reserve is measured on the map's lanes");
                }
            }
        }
        this.drainPercentPerMetre = drainPercentPerMetre;
        this.marginPercent = marginPercent;
        this.routes = routes != null ? routes : this::shortest;
    }

    public String dock() {
        return dock;
    }

    public double marginPercent() {
        return marginPercent;
    }

    /** The metres of a route (nodes in order, each joined to the next by an edge of the map). */
    public double metres(List<String> route) {
        double m = 0;
        for (int i = 1; i < route.size(); i++) {
            m += map.length(route.get(i - 1), route.get(i)).orElseThrow();
        }
        return m;
    }

    /** The route the robot drives from {@code node} to the dock (just the dock when it stands there). */
    public List<String> wayToDock(String node) {
        return node.equals(dock) ? List.of(dock) : routes.apply(node, dock);
    }

    /** What the robot standing at {@code node} keeps in hand, percent: the way to the dock from there and the margin. */
    public double reserveAt(String node) {
        return metres(wayToDock(node)) * drainPercentPerMetre + marginPercent;
    }

    /** The charge the leg needs, percent: the leg, then the way from its end to the dock, then the margin. */
    public double needed(List<String> leg) {
        if (leg.isEmpty()) {
            throw new IllegalArgumentException("a leg has at least one node");
        }
        return metres(leg) * drainPercentPerMetre + reserveAt(leg.get(leg.size() - 1));
    }

    /** Whether a robot with this charge (percent) may take the leg, or goes to the dock first. */
    public boolean covers(double chargePercent, List<String> leg) {
        return chargePercent >= needed(leg);
    }

    /** {@code 34.0 % needed: 21.5 m of the leg, 33.0 m back to lobby.dock, 12 % margin}, for a log line. */
    public String explain(List<String> leg) {
        String end = leg.get(leg.size() - 1);
        return String.format(Locale.ROOT, "%.1f %% needed: %.1f m of the leg, %.1f m back to %s, %.0f %% margin", needed(leg), metres(leg),
                metres(wayToDock(end)), dock, marginPercent);
    }

    /** The shortest route by metres (Dijkstra; ties by node name, so that the answer does not depend on hashing). */
    private List<String> shortest(String from, String to) {
        Map<String, Double> dist = new HashMap<>();
        Map<String, String> previous = new HashMap<>();
        record Open(String node, double metres) {
        }
        PriorityQueue<Open> open = new PriorityQueue<>((x, y) -> x.metres != y.metres ? Double.compare(x.metres, y.metres) : x.node.compareTo(y.node));
        dist.put(from, 0.0);
        open.add(new Open(from, 0));
        while (!open.isEmpty()) {
            Open o = open.poll();
            if (o.metres > dist.get(o.node)) {
                continue;
            }
            if (o.node.equals(to)) {
                break;
            }
            for (String n : map.neighbours(o.node)) {
                OptionalDouble l = map.length(o.node, n);
                double d = o.metres + l.orElseThrow();
                if (d < dist.getOrDefault(n, Double.POSITIVE_INFINITY)) {
                    dist.put(n, d);
                    previous.put(n, o.node);
                    open.add(new Open(n, d));
                }
            }
        }
        if (!dist.containsKey(to)) {
            throw new IllegalArgumentException("no way from '" + from + "' to '" + to + "' on the traffic map");
        }
        List<String> route = new ArrayList<>();
        for (String x = to; x != null; x = previous.get(x)) {
            route.add(0, x);
        }
        return route;
    }
}
