package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * An immutable floor plan: rooms and corridors (axis-aligned rectangles, metres), walls derived from
 * the room borders minus door gaps and openings, doorways, a waypoint graph and initial items.
 * Build one with {@link #builder()}:
 *
 * <pre>{@code
 * FloorPlan plan = FloorPlan.builder()
 *     .corridor("hall", 0, 4, 20, 6)
 *     .room("storage", 0, 0, 6, 4).door("storageDoor", "storage", "hall", 3, 4)
 *     .roomWaypoints().doorWaypoints().waypoint("hallWest", 1, 5)
 *     .lineOfSightEdges(0.35)
 *     .item("box", 1, 1)
 *     .build();
 * }</pre>
 *
 * All iteration orders are declaration orders, so simulations over a plan are deterministic.
 */
public final class FloorPlan {
    private final List<Room> rooms;
    private final List<Wall> walls;
    private final List<Doorway> doorways;
    private final Map<String, Waypoint> waypoints;
    private final List<GraphEdge> edges;
    private final Map<String, List<GraphEdge>> adjacency;
    private final List<ItemPlacement> items;
    private final double wallThickness;
    private final Rect bounds;
    private final WallGrid wallGrid;

    private FloorPlan(List<Room> rooms, List<Wall> walls, List<Doorway> doorways, Map<String, Waypoint> waypoints,
                      List<GraphEdge> edges, List<ItemPlacement> items, double wallThickness) {
        this.rooms = List.copyOf(rooms);
        this.walls = List.copyOf(walls);
        this.doorways = List.copyOf(doorways);
        this.waypoints = Collections.unmodifiableMap(new LinkedHashMap<>(waypoints));
        this.edges = List.copyOf(edges);
        this.items = List.copyOf(items);
        this.wallThickness = wallThickness;
        Map<String, List<GraphEdge>> adj = new LinkedHashMap<>();
        waypoints.keySet().forEach(n -> adj.put(n, new ArrayList<>()));
        for (GraphEdge e : edges) {
            adj.get(e.from()).add(e);
            adj.get(e.to()).add(e);
        }
        this.adjacency = adj;
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
        for (Room r : rooms) {
            minX = Math.min(minX, r.bounds().minX());
            minY = Math.min(minY, r.bounds().minY());
            maxX = Math.max(maxX, r.bounds().maxX());
            maxY = Math.max(maxY, r.bounds().maxY());
        }
        this.bounds = new Rect(minX, minY, maxX, maxY);
        this.wallGrid = new WallGrid(this.walls, bounds);
    }

    /** Starts an empty floor plan. */
    public static Builder builder() {
        return new Builder();
    }

    public List<Room> rooms() {
        return rooms;
    }

    public List<Wall> walls() {
        return walls;
    }

    public List<Doorway> doorways() {
        return doorways;
    }

    /** Waypoints in declaration order. */
    public List<Waypoint> waypoints() {
        return List.copyOf(waypoints.values());
    }

    public List<GraphEdge> edges() {
        return edges;
    }

    public List<ItemPlacement> items() {
        return items;
    }

    /** Wall thickness in metres. */
    public double wallThickness() {
        return wallThickness;
    }

    /** Bounding box of all rooms, metres. */
    public Rect bounds() {
        return bounds;
    }

    /** @throws IllegalArgumentException if no waypoint has this name */
    public Waypoint waypoint(String name) {
        Waypoint w = name == null ? null : waypoints.get(name);
        if (w == null) {
            throw new IllegalArgumentException("unknown waypoint '" + name + "'; known: " + waypoints.keySet());
        }
        return w;
    }

    public boolean hasWaypoint(String name) {
        return name != null && waypoints.containsKey(name);
    }

    /** @throws IllegalArgumentException if no room has this name */
    public Room room(String name) {
        for (Room r : rooms) {
            if (r.name().equals(name)) {
                return r;
            }
        }
        throw new IllegalArgumentException("unknown room '" + name + "'");
    }

    /** @throws IllegalArgumentException if no doorway has this name */
    public Doorway doorway(String name) {
        for (Doorway d : doorways) {
            if (d.name().equals(name)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown door '" + name + "'");
    }

    /** Edges incident to the waypoint, in declaration order. */
    public List<GraphEdge> edgesOf(String waypoint) {
        waypoint(waypoint);
        return Collections.unmodifiableList(adjacency.get(waypoint));
    }

    /** The edge between two waypoints, if declared or derived. */
    public Optional<GraphEdge> edge(String a, String b) {
        for (GraphEdge e : edgesOf(a)) {
            if (e.other(a).equals(b)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** The room containing {@code p}; where rooms touch, the first declared wins. */
    public Optional<Room> roomAt(Vec2 p) {
        for (Room r : rooms) {
            if (r.bounds().contains(p)) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }

    /** The waypoint closest to {@code p} (straight-line distance; ties: first declared). */
    public Waypoint nearestWaypoint(Vec2 p) {
        Waypoint best = null;
        double bestD = Double.POSITIVE_INFINITY;
        for (Waypoint w : waypoints.values()) {
            double d = w.position().distance(p);
            if (d < bestD) {
                bestD = d;
                best = w;
            }
        }
        return best;
    }

    /** Distance from {@code p} to the nearest wall surface, metres. */
    public double wallClearance(Vec2 p) {
        double best = Double.POSITIVE_INFINITY;
        for (Wall w : walls) {
            best = Math.min(best, Segments.pointDistance(p, w.a(), w.b()) - wallThickness / 2);
        }
        return best;
    }

    /**
     * Whether a disc of radius {@code clearance} can move straight from {@code a} to {@code b}
     * without touching a wall (doors are treated as open) and without leaving the rooms.
     */
    public boolean isClear(Vec2 a, Vec2 b, double clearance) {
        if (roomAt(a).isEmpty() || roomAt(b).isEmpty() || roomAt(a.plus(b).times(0.5)).isEmpty()) {
            return false;
        }
        return !wallGrid.anyNearSegment(a, b, clearance + wallThickness / 2);
    }

    /** Whether {@code p} is at least {@code clearance} from every wall surface: {@code wallClearance(p) >= clearance}, without visiting every wall. */
    public boolean clearOfWalls(Vec2 p, double clearance) {
        return !wallGrid.anyNearPoint(p, clearance, wallThickness / 2);
    }

    /** The first doorway (declaration order) that the segment {@code a}-{@code b} passes through. */
    public Optional<Doorway> doorCrossed(Vec2 a, Vec2 b) {
        for (Doorway d : doorways) {
            if (Segments.intersect(a, b, d.end1(), d.end2())) {
                return Optional.of(d);
            }
        }
        return Optional.empty();
    }

    /** How many doorways the segment {@code a}-{@code b} passes through. */
    public int doorsCrossed(Vec2 a, Vec2 b) {
        int n = 0;
        for (Doorway d : doorways) {
            if (Segments.intersect(a, b, d.end1(), d.end2())) {
                n++;
            }
        }
        return n;
    }

    /** Fluent builder; see {@link FloorPlan} for an example. Not thread-safe. */
    public static final class Builder {
        private static final double EPS = 1e-6;
        private final List<Room> rooms = new ArrayList<>();
        private final List<Doorway> doorways = new ArrayList<>();
        private final List<String[]> openings = new ArrayList<>();
        private final Map<String, Waypoint> waypoints = new LinkedHashMap<>();
        private final List<String[]> declaredEdges = new ArrayList<>();
        private final List<ItemPlacement> items = new ArrayList<>();
        private double wallThickness = 0.1;
        private double losClearance = -1;
        private boolean roomWaypoints;
        private boolean doorWaypoints;

        private Builder() {
        }

        /** Wall thickness in metres (default 0.1). */
        public Builder wallThickness(double metres) {
            this.wallThickness = Checks.positive("wall thickness", metres);
            return this;
        }

        /** Adds a room spanning [x0,x1] x [y0,y1] metres. */
        public Builder room(String name, double x0, double y0, double x1, double y1) {
            return area(name, x0, y0, x1, y1, false);
        }

        /** Adds a corridor spanning [x0,x1] x [y0,y1] metres. */
        public Builder corridor(String name, double x0, double y0, double x1, double y1) {
            return area(name, x0, y0, x1, y1, true);
        }

        private Builder area(String name, double x0, double y0, double x1, double y1, boolean corridor) {
            Checks.name("room name", name);
            for (Room r : rooms) {
                if (r.name().equals(name)) {
                    throw new IllegalArgumentException("duplicate room '" + name + "'");
                }
            }
            rooms.add(new Room(name, new Rect(x0, y0, x1, y1), corridor));
            return this;
        }

        /** Adds a 1.2 m wide door centred at (x, y) metres on the wall shared by two rooms. */
        public Builder door(String name, String roomA, String roomB, double x, double y) {
            return door(name, roomA, roomB, x, y, 1.2);
        }

        /** Adds a door of {@code width} metres centred at (x, y) metres on the wall shared by two rooms. */
        public Builder door(String name, String roomA, String roomB, double x, double y, double width) {
            Checks.name("door name", name);
            Checks.positive("door width", width);
            Room a = findRoom(roomA);
            Room b = findRoom(roomB);
            Vec2 c = new Vec2(x, y);
            Boolean horizontal = sharedSideOrientation(a.bounds(), b.bounds(), c);
            if (horizontal == null) {
                throw new IllegalArgumentException("door '" + name + "' at " + c + " is not on a wall shared by rooms '"
                        + roomA + "' and '" + roomB + "'");
            }
            for (Doorway d : doorways) {
                if (d.name().equals(name)) {
                    throw new IllegalArgumentException("duplicate door '" + name + "'");
                }
            }
            doorways.add(new Doorway(name, roomA, roomB, c, width, horizontal, true));
            return this;
        }

        /** Removes the whole wall shared by two touching rooms (e.g. two corridor parts). */
        public Builder opening(String roomA, String roomB) {
            Room a = findRoom(roomA);
            Room b = findRoom(roomB);
            if (sharedSegment(a.bounds(), b.bounds()) == null) {
                throw new IllegalArgumentException("rooms '" + roomA + "' and '" + roomB + "' share no wall");
            }
            openings.add(new String[] {roomA, roomB});
            return this;
        }

        /** Adds a named waypoint at (x, y) metres; it must lie inside a room. */
        public Builder waypoint(String name, double x, double y) {
            Checks.name("waypoint name", name);
            if (waypoints.containsKey(name)) {
                throw new IllegalArgumentException("duplicate waypoint '" + name + "'");
            }
            waypoints.put(name, new Waypoint(name, new Vec2(x, y)));
            return this;
        }

        /** At build time, adds a waypoint named after each room at its centre (unless that name exists). */
        public Builder roomWaypoints() {
            roomWaypoints = true;
            return this;
        }

        /** At build time, adds a waypoint named after each door at its centre (unless that name exists). */
        public Builder doorWaypoints() {
            doorWaypoints = true;
            return this;
        }

        /** Declares an undirected edge between two waypoints. */
        public Builder edge(String a, String b) {
            Checks.name("edge end", a);
            Checks.name("edge end", b);
            if (a.equals(b)) {
                throw new IllegalArgumentException("edge from waypoint '" + a + "' to itself");
            }
            declaredEdges.add(new String[] {a, b});
            return this;
        }

        /**
         * At build time, connects every pair of waypoints whose straight segment keeps
         * {@code clearance} metres from all walls (typically the robot radius plus a margin).
         */
        public Builder lineOfSightEdges(double clearance) {
            this.losClearance = Checks.positive("line-of-sight clearance", clearance);
            return this;
        }

        /** An item present at start, at (x, y) metres inside a room. */
        public Builder item(String name, double x, double y) {
            Checks.name("item name", name);
            for (ItemPlacement i : items) {
                if (i.name().equals(name)) {
                    throw new IllegalArgumentException("duplicate item '" + name + "'");
                }
            }
            items.add(new ItemPlacement(name, new Vec2(x, y)));
            return this;
        }

        /** @throws IllegalArgumentException if the plan is inconsistent (no rooms, waypoint outside rooms...) */
        public FloorPlan build() {
            if (rooms.isEmpty()) {
                throw new IllegalArgumentException("a floor plan needs at least one room");
            }
            Map<String, Waypoint> wps = new LinkedHashMap<>(waypoints);
            if (roomWaypoints) {
                rooms.forEach(r -> wps.putIfAbsent(r.name(), new Waypoint(r.name(), r.bounds().center())));
            }
            if (doorWaypoints) {
                doorways.forEach(d -> wps.putIfAbsent(d.name(), new Waypoint(d.name(), d.center())));
            }
            List<Wall> walls = deriveWalls();
            for (Waypoint w : wps.values()) {
                requireInside("waypoint '" + w.name() + "'", w.position());
            }
            for (ItemPlacement i : items) {
                requireInside("item '" + i.name() + "'", i.position());
            }
            FloorPlan geometry = new FloorPlan(rooms, walls, doorways, wps, List.of(), items, wallThickness);
            List<GraphEdge> edges = new ArrayList<>();
            for (String[] e : declaredEdges) {
                Vec2 a = geometry.waypoint(e[0]).position();
                Vec2 b = geometry.waypoint(e[1]).position();
                if (geometry.doorsCrossed(a, b) > 1) {
                    throw new IllegalArgumentException("edge " + e[0] + "-" + e[1] + " passes through more than one door;"
                            + " add a waypoint in between");
                }
                addEdge(edges, geometry, geometry.waypoint(e[0]), geometry.waypoint(e[1]));
            }
            if (losClearance > 0) {
                List<Waypoint> list = new ArrayList<>(wps.values());
                for (int i = 0; i < list.size(); i++) {
                    for (int j = i + 1; j < list.size(); j++) {
                        Vec2 a = list.get(i).position();
                        Vec2 b = list.get(j).position();
                        if (geometry.isClear(a, b, losClearance) && geometry.doorsCrossed(a, b) <= 1) {
                            addEdge(edges, geometry, list.get(i), list.get(j));
                        }
                    }
                }
            }
            return new FloorPlan(rooms, walls, doorways, wps, edges, items, wallThickness);
        }

        private static void addEdge(List<GraphEdge> edges, FloorPlan geometry, Waypoint a, Waypoint b) {
            for (GraphEdge e : edges) {
                if ((e.from().equals(a.name()) && e.to().equals(b.name()))
                        || (e.from().equals(b.name()) && e.to().equals(a.name()))) {
                    return;
                }
            }
            String door = geometry.doorCrossed(a.position(), b.position()).map(Doorway::name).orElse(null);
            edges.add(new GraphEdge(a.name(), b.name(), a.position().distance(b.position()), door));
        }

        private void requireInside(String what, Vec2 p) {
            for (Room r : rooms) {
                if (r.bounds().contains(p)) {
                    return;
                }
            }
            throw new IllegalArgumentException(what + " at " + p + " is outside every room");
        }

        private Room findRoom(String name) {
            for (Room r : rooms) {
                if (r.name().equals(name)) {
                    return r;
                }
            }
            throw new IllegalArgumentException("unknown room '" + name + "'");
        }

        /** TRUE if c lies on a horizontal side of both rooms, FALSE if vertical, null if neither. */
        private static Boolean sharedSideOrientation(Rect a, Rect b, Vec2 c) {
            double[] s = sharedSegment(a, b);
            if (s == null) {
                return null;
            }
            boolean horizontal = s[1] == s[3];
            boolean on = horizontal
                    ? Math.abs(c.y() - s[1]) < EPS && c.x() > s[0] - EPS && c.x() < s[2] + EPS
                    : Math.abs(c.x() - s[0]) < EPS && c.y() > s[1] - EPS && c.y() < s[3] + EPS;
            return on ? horizontal : null;
        }

        /** The shared border of two touching rectangles as {x0, y0, x1, y1}, or null. */
        private static double[] sharedSegment(Rect a, Rect b) {
            double x0 = Math.max(a.minX(), b.minX());
            double x1 = Math.min(a.maxX(), b.maxX());
            double y0 = Math.max(a.minY(), b.minY());
            double y1 = Math.min(a.maxY(), b.maxY());
            boolean touchY = Math.abs(a.maxY() - b.minY()) < EPS || Math.abs(b.maxY() - a.minY()) < EPS;
            boolean touchX = Math.abs(a.maxX() - b.minX()) < EPS || Math.abs(b.maxX() - a.minX()) < EPS;
            if (touchY && x1 - x0 > EPS) {
                double y = Math.abs(a.maxY() - b.minY()) < EPS ? a.maxY() : a.minY();
                return new double[] {x0, y, x1, y};
            }
            if (touchX && y1 - y0 > EPS) {
                double x = Math.abs(a.maxX() - b.minX()) < EPS ? a.maxX() : a.minX();
                return new double[] {x, y0, x, y1};
            }
            return null;
        }

        private List<Wall> deriveWalls() {
            List<Wall> walls = new ArrayList<>();
            for (Room r : rooms) {
                Rect b = r.bounds();
                side(walls, r, true, b.minY(), b.minX(), b.maxX());
                side(walls, r, true, b.maxY(), b.minX(), b.maxX());
                side(walls, r, false, b.minX(), b.minY(), b.maxY());
                side(walls, r, false, b.maxX(), b.minY(), b.maxY());
            }
            return merged(walls);
        }

        /** Neighbouring rooms produce the same wall twice: merge collinear overlapping pieces into one. */
        private static List<Wall> merged(List<Wall> walls) {
            List<Wall> out = new ArrayList<>();
            boolean[] used = new boolean[walls.size()];
            for (int i = 0; i < walls.size(); i++) {
                if (used[i]) {
                    continue;
                }
                Wall w = walls.get(i);
                boolean horizontal = Math.abs(w.a().y() - w.b().y()) < EPS;
                double at = horizontal ? w.a().y() : w.a().x();
                double lo = horizontal ? w.a().x() : w.a().y();
                double hi = horizontal ? w.b().x() : w.b().y();
                boolean grown = true;
                while (grown) {
                    grown = false;
                    for (int j = i + 1; j < walls.size(); j++) {
                        Wall v = walls.get(j);
                        boolean vh = Math.abs(v.a().y() - v.b().y()) < EPS;
                        double vat = vh ? v.a().y() : v.a().x();
                        double vlo = vh ? v.a().x() : v.a().y();
                        double vhi = vh ? v.b().x() : v.b().y();
                        if (!used[j] && vh == horizontal && Math.abs(vat - at) < EPS && vlo <= hi + EPS && vhi >= lo - EPS) {
                            used[j] = true;
                            lo = Math.min(lo, vlo);
                            hi = Math.max(hi, vhi);
                            grown = true;
                        }
                    }
                }
                out.add(wall(horizontal, at, lo, hi));
            }
            return out;
        }

        /** One side of a room (fixed coordinate {@code at}, spanning lo..hi) minus door gaps and openings. */
        private void side(List<Wall> walls, Room room, boolean horizontal, double at, double lo, double hi) {
            List<double[]> gaps = new ArrayList<>();
            for (Doorway d : doorways) {
                if (d.horizontal() == horizontal && (d.roomA().equals(room.name()) || d.roomB().equals(room.name()))) {
                    double fixed = horizontal ? d.center().y() : d.center().x();
                    double along = horizontal ? d.center().x() : d.center().y();
                    if (Math.abs(fixed - at) < EPS) {
                        gaps.add(new double[] {along - d.width() / 2, along + d.width() / 2});
                    }
                }
            }
            for (String[] o : openings) {
                String other = o[0].equals(room.name()) ? o[1] : o[1].equals(room.name()) ? o[0] : null;
                if (other == null) {
                    continue;
                }
                double[] s = sharedSegment(room.bounds(), findRoom(other).bounds());
                boolean sh = s[1] == s[3];
                if (sh == horizontal && Math.abs((horizontal ? s[1] : s[0]) - at) < EPS) {
                    gaps.add(horizontal ? new double[] {s[0], s[2]} : new double[] {s[1], s[3]});
                }
            }
            gaps.sort((g1, g2) -> Double.compare(g1[0], g2[0]));
            double cursor = lo;
            for (double[] g : gaps) {
                if (g[0] > cursor + EPS) {
                    walls.add(wall(horizontal, at, cursor, Math.min(g[0], hi)));
                }
                cursor = Math.max(cursor, g[1]);
            }
            if (hi > cursor + EPS) {
                walls.add(wall(horizontal, at, cursor, hi));
            }
        }

        private static Wall wall(boolean horizontal, double at, double from, double to) {
            return horizontal ? new Wall(new Vec2(from, at), new Vec2(to, at)) : new Wall(new Vec2(at, from), new Vec2(at, to));
        }
    }
}
