package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.sim.FloorPlan;
import org.triad.sim.GraphEdge;
import org.triad.sim.Room;
import org.triad.sim.Vec2;

/**
 * The hospital floor of the models (Morning.state) as a simulated building, metres: a ring corridor
 * c1-c2-c3 (north) and c4-c5-c6 (south), joined by side corridors c1-c4 (west) and c3-c6 (east), with
 * storage, x-ray and ward 1 north of c1, c2, c3 and the lobby, ward 3 and ward 2 south of c4, c5, c6.
 * The north corridor has a fire door {@value #FIRE_DOOR} between c2 and c3.
 *
 * <p>Every model edge ({@code Building.adj}) is a fixed route of simulator waypoints: straight for most,
 * round the corners (waypoints {@code nw, sw, ne, se}) for the side corridors. Waypoint names equal the
 * model's object names.
 */
public final class HospitalFloor {
    /** The door between c2 and c3 that the fault scenarios close. */
    public static final String FIRE_DOOR = "fireDoor";
    /** Corridor waypoints of the model, in declaration order. */
    public static final List<String> CORRIDOR_WAYPOINTS = List.of("c1", "c2", "c3", "c4", "c5", "c6");
    /** Rooms of the model, in declaration order. */
    public static final List<String> ROOMS = List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby");
    /** Items of the model, all in storage at the start. */
    public static final List<String> ITEMS = List.of("gauze", "syringe", "bandage");
    /** People of the model with where they stand at the start (Alice a visitor, Bob a patient). */
    public static final Map<String, Vec2> PEOPLE = orderedMap("alice", new Vec2(5.6, 2.0), "bob", new Vec2(21.2, 3.4));
    /** Walking speeds, m/s: Bob, a patient, walks slower than the robot drives, so it can keep up with him round corners. */
    public static final Map<String, Double> WALKING_SPEED = Map.of("alice", 1.0, "bob", 0.7);
    /** Where the robot starts (the model's Morning: in the lobby). */
    public static final String ROBOT_START = "lobby";
    /**
     * How far (m) someone may stand from a waypoint and still be at it: a guided person waits up to 2 m
     * behind the robot, a following robot keeps up to 2.5 m behind the person.
     */
    public static final double AT_TOLERANCE = 2.6;

    private final FloorPlan plan;
    private final Map<List<String>, List<String>> routes = new LinkedHashMap<>();

    /** A room off the ring: its corridor waypoint, its door's centre (m) and whether it lies north of the ring. */
    private record RoomSpec(String name, String corridorWaypoint, String corridor, double x0, double x1, boolean north) {
        double doorX() {
            return (x0 + x1) / 2;
        }
    }

    private static final List<RoomSpec> ROOM_SPECS = List.of(
            new RoomSpec("storage", "c1", "northCorridor", 0, 8, true),
            new RoomSpec("xray", "c2", "northCorridor", 8, 16, true),
            new RoomSpec("ward1", "c3", "northEastCorridor", 16, 24, true),
            new RoomSpec("lobby", "c4", "southCorridor", 0, 8, false),
            new RoomSpec("ward3", "c5", "southCorridor", 8, 16, false),
            new RoomSpec("ward2", "c6", "southCorridor", 16, 24, false));

    public HospitalFloor() {
        FloorPlan.Builder b = FloorPlan.builder()
                .corridor("southCorridor", 0, 5, 24, 7.4)
                .corridor("westCorridor", 0, 7.4, 2.4, 13).corridor("eastCorridor", 21.6, 7.4, 24, 13)
                .corridor("northCorridor", 0, 13, 16, 15.4).corridor("northEastCorridor", 16, 13, 24, 15.4)
                .opening("southCorridor", "westCorridor").opening("southCorridor", "eastCorridor")
                .opening("westCorridor", "northCorridor").opening("eastCorridor", "northEastCorridor")
                .door(FIRE_DOOR, "northCorridor", "northEastCorridor", 16, 14.2, 1.8)
                .waypoint("c1", 4, 14.2).waypoint("c2", 12, 14.2).waypoint("c3", 20, 14.2)
                .waypoint("c4", 4, 6.2).waypoint("c5", 12, 6.2).waypoint("c6", 20, 6.2)
                .waypoint("nw", 1.2, 14.2).waypoint("ne", 22.8, 14.2).waypoint("sw", 1.2, 6.2).waypoint("se", 22.8, 6.2);
        for (RoomSpec r : ROOM_SPECS) {
            double wall = r.north() ? 15.4 : 5;
            double inside = r.north() ? 1 : -1;
            b.room(r.name(), r.x0(), r.north() ? wall : 0, r.x1(), r.north() ? wall + 5 : wall)
                    .door(r.name() + "Door", r.name(), r.corridor(), r.doorX(), wall)
                    .waypoint(r.name(), r.doorX(), wall + inside * 2.5);
            route(b, r.name(), r.corridorWaypoint());
            // a waypoint just inside the door: people leaving from beside the room's centre (where the robot
            // stands) head for it instead of walking through the robot
            b.waypoint(r.name() + "Entry", r.doorX(), wall + inside).edge(r.name() + "Entry", r.name())
                    .edge(r.name() + "Entry", r.corridorWaypoint());
        }
        b.item("gauze", 3.4, 18.5).item("syringe", 4.6, 18.5).item("bandage", 4.0, 18.8);
        route(b, "c1", "c2");
        route(b, "c2", "c3");
        route(b, "c4", "c5");
        route(b, "c5", "c6");
        route(b, "c1", "nw", "sw", "c4");
        route(b, "c3", "ne", "se", "c6");
        this.plan = b.build();
    }

    private void route(FloorPlan.Builder b, String... via) {
        List<String> path = List.of(via);
        for (int i = 1; i < path.size(); i++) {
            b.edge(path.get(i - 1), path.get(i));
        }
        List<String> back = new ArrayList<>(path);
        Collections.reverse(back);
        routes.put(List.of(path.get(0), path.get(path.size() - 1)), path);
        routes.put(List.of(back.get(0), back.get(back.size() - 1)), List.copyOf(back));
    }

    public FloorPlan plan() {
        return plan;
    }

    /** All model waypoints (corridor waypoints, then rooms). */
    public List<String> modelWaypoints() {
        List<String> all = new ArrayList<>(CORRIDOR_WAYPOINTS);
        all.addAll(ROOMS);
        return all;
    }

    /** The simulator waypoints from {@code src} to {@code dst} for a model edge, or empty if the model has no such edge. */
    public Optional<List<String>> route(String src, String dst) {
        return Optional.ofNullable(routes.get(List.of(src, dst)));
    }

    /** The doors a model edge passes through (in route order). */
    public List<String> doorsOn(List<String> route) {
        List<String> doors = new ArrayList<>();
        for (int i = 1; i < route.size(); i++) {
            GraphEdge e = plan.edge(route.get(i - 1), route.get(i)).orElseThrow();
            if (e.door() != null) {
                doors.add(e.door());
            }
        }
        return doors;
    }

    /** The model waypoint a position belongs to: the room it lies in, else the nearest corridor waypoint. */
    public String waypointAt(Vec2 p) {
        Optional<String> room = plan.roomAt(p).map(Room::name).filter(ROOMS::contains);
        if (room.isPresent()) {
            return room.get();
        }
        String best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (String w : CORRIDOR_WAYPOINTS) {
            double d = plan.waypoint(w).position().distance(p);
            if (d < bestDistance) {
                best = w;
                bestDistance = d;
            }
        }
        return best;
    }

    /**
     * The model waypoint of someone at {@code p} who was last known at {@code known} (may be null): the
     * known one while within {@link #AT_TOLERANCE}, else {@link #waypointAt(Vec2)}.
     */
    public String waypointAt(Vec2 p, String known) {
        if (known != null && plan.waypoint(known).position().distance(p) <= AT_TOLERANCE) {
            return known;
        }
        return waypointAt(p);
    }

    private static Map<String, Vec2> orderedMap(String k1, Vec2 v1, String k2, Vec2 v2) {
        Map<String, Vec2> m = new LinkedHashMap<>();
        m.put(k1, v1);
        m.put(k2, v2);
        return Collections.unmodifiableMap(m);
    }
}
