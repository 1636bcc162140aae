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
 * <p>Two floors, laid side by side in the plane so that their bodies never touch (one dyn4j world holds both):
 * floor 0 is the ring above, with the pharmacy west of the west corridor (its door {@value #PHARMACY_DOOR} is closed
 * and opened by the building on request, from waypoint c0) and the lift's floor-0 cabin ({@code lift0}) east of the
 * east corridor (landing c7). Floor 1 lies 8 m east of floor 0's lift: the floor-1 cabin ({@code lift1}), a corridor
 * d1-d2 and ward 4 (north) and ward 5 (south) off d2. The lift {@value #LIFT} carries whoever stands in one cabin to
 * the same spot of the other in {@value #LIFT_SECONDS_PER_FLOOR} simulated seconds (see {@link org.triad.sim.Lift}).
 *
 * <p>Every model edge ({@code Building.adj}) is a fixed route of simulator waypoints: straight for most,
 * round the corners (waypoints {@code nw, sw, ne, se}) for the side corridors. Waypoint names equal the
 * model's object names.
 */
public final class HospitalFloor {
    /** The door between c2 and c3 that the fault scenarios close. */
    public static final String FIRE_DOOR = "fireDoor";
    /** The pharmacy's door: closed, the building opens it on request ({@code Building.passDoor}). */
    public static final String PHARMACY_DOOR = "pharmacyDoor";
    /** The lift between floor 0 (landing c7, cabin lift0) and floor 1 (landing d1, cabin lift1). */
    public static final String LIFT = "lift";
    /** Simulated seconds the lift travels per floor, once its door has closed. */
    public static final double LIFT_SECONDS_PER_FLOOR = 8;
    /** Corridor waypoints of the model, in declaration order (floor 0, then the lift's cabins, then floor 1). */
    public static final List<String> CORRIDOR_WAYPOINTS = List.of("c1", "c2", "c3", "c4", "c5", "c6", "c0", "c7", "lift0", "lift1", "d1", "d2");
    /** Rooms of the model, in declaration order. */
    public static final List<String> ROOMS = List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby", "pharmacy", "ward4", "ward5");
    /** Items of the model with the room each lies in at the start. */
    public static final Map<String, String> ITEM_ROOMS = orderedMap(List.of("gauze", "syringe", "bandage", "insulin"),
            List.of("storage", "storage", "storage", "pharmacy"));
    /** Items of the model. */
    public static final List<String> ITEMS = List.copyOf(ITEM_ROOMS.keySet());
    /** The floor of every model waypoint that is not on floor 0. */
    public static final Map<String, Integer> UPPER_FLOOR_WAYPOINTS = Map.of("lift1", 1, "d1", 1, "d2", 1, "ward4", 1, "ward5", 1);
    /** A lift's landing: the model waypoint before its door on a floor, and the cabin's waypoint (and room) there. */
    public record LiftLanding(String lift, int floor, String landing, String cabin, String door) {
    }
    /** The lift's landings, floor 0 first. */
    public static final List<LiftLanding> LIFT_LANDINGS = List.of(new LiftLanding(LIFT, 0, "c7", "lift0", "liftDoor0"),
            new LiftLanding(LIFT, 1, "d1", "lift1", "liftDoor1"));
    /** A door the building opens on request: its name and the model waypoints on either side. */
    public record ControlledDoor(String door, String a, String b) {
    }
    /** The doors the building opens on request ({@code Building.doorway} facts, both ways). */
    public static final List<ControlledDoor> CONTROLLED_DOORS = List.of(new ControlledDoor(PHARMACY_DOOR, "c0", "pharmacy"));
    /** People of the model with where they stand at the start (Alice a visitor, Bob a patient). */
    public static final Map<String, Vec2> PEOPLE = orderedMap("alice", new Vec2(5.6, 2.0), "bob", new Vec2(21.2, 3.4));
    /**
     * The people who walk their own way ({@code Building.walksAhead}): Bob, a patient on his feet, whom the courier
     * follows; Alice, a visitor, does not know the way and is guided.
     */
    public static final java.util.Set<String> WALKING_AHEAD = java.util.Set.of("bob");
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
    /** Model edges the building must help with (through a controlled door, into or out of a lift's cabin): not corridors. */
    private final java.util.Set<List<String>> passages = new java.util.HashSet<>();

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
        // the lobby's parking spots and dock, each a leaf off the lobby's waypoint (a route through a leaf is never shorter,
        // so nobody's way is planned through a parked courier)
        LobbyParking.places().forEach((place, at) -> {
            b.waypoint(place, at.x(), at.y());
            route(b, place, LobbyParking.HALL);
        });
        route(b, "c1", "c2");
        route(b, "c2", "c3");
        route(b, "c4", "c5");
        route(b, "c5", "c6");
        route(b, "c1", "nw", "sw", "c4");
        route(b, "c3", "ne", "se", "c6");
        // floor 0: the pharmacy west of the west corridor behind a controlled door, the lift's cabin east of the east corridor
        b.room("pharmacy", -8, 7.4, 0, 13).door(PHARMACY_DOOR, "pharmacy", "westCorridor", 0, 10.2, 1.4)
                .waypoint("pharmacy", -4, 10.2).waypoint("c0", 1.2, 10.2).waypoint("c7", 22.8, 10.2)
                .room("lift0", 24, 8.7, 27, 11.7).door("liftDoor0", "eastCorridor", "lift0", 24, 10.2, 1.6).waypoint("lift0", 25.5, 10.2);
        // within the courier's reach (1 m) of the pharmacy's waypoint, as the storage's items of theirs: the models' pick drives no
        // metres, and an item further away would make the courier drive to it and back beyond what the plan drains
        b.item("insulin", -4.5, 10.9);
        route(b, "c1", "nw", "c0");
        route(b, "c0", "sw", "c4");
        route(b, "c3", "ne", "c7");
        route(b, "c7", "se", "c6");
        passage(b, "c0", "pharmacy");
        passage(b, "c7", "lift0");
        // floor 1, 8 m east of floor 0's cabin
        b.room("lift1", 35, 8.7, 38, 11.7).corridor("floor1Corridor", 38, 9, 54, 11.4)
                .door("liftDoor1", "lift1", "floor1Corridor", 38, 10.2, 1.6).waypoint("lift1", 36.5, 10.2)
                .waypoint("d1", 39.4, 10.2).waypoint("d2", 47, 10.2)
                .room("ward4", 43, 11.4, 51, 16.4).door("ward4Door", "ward4", "floor1Corridor", 47, 11.4).waypoint("ward4", 47, 13.9)
                .room("ward5", 43, 4, 51, 9).door("ward5Door", "ward5", "floor1Corridor", 47, 9).waypoint("ward5", 47, 6.5);
        route(b, "d1", "d2");
        route(b, "ward4", "d2");
        route(b, "ward5", "d2");
        passage(b, "lift1", "d1");
        this.plan = b.build();
    }

    /** A model edge through a controlled door or a lift's door: drivable when the building has opened it, not a corridor. */
    private void passage(FloorPlan.Builder b, String a, String z) {
        route(b, a, z);
        passages.add(List.of(a, z));
        passages.add(List.of(z, a));
    }

    /** Puts the building's devices into the simulation: the lift (standing at floor 0) and the controlled doors, closed. */
    public void equip(org.triad.sim.Simulation sim) {
        List<org.triad.sim.Lift.Landing> landings = new ArrayList<>();
        for (LiftLanding l : LIFT_LANDINGS) {
            landings.add(new org.triad.sim.Lift.Landing(l.floor(), l.cabin(), l.door()));
        }
        sim.addLift(LIFT, landings, LIFT_SECONDS_PER_FLOOR, 0);
        for (ControlledDoor d : CONTROLLED_DOORS) {
            sim.closeDoor(d.door());
        }
    }

    /** Where floor 1 begins in the simulation's plane (x, metres): floor 0 lies west of it, floor 1 east (8 m east of floor 0's cabin). */
    public static final double FLOOR_1_WEST_X = 31;

    /** The floor of a point of the simulation's plane (0 or 1): the floors lie side by side in one dyn4j world. */
    public static int floorAt(double x) {
        return x >= FLOOR_1_WEST_X ? 1 : 0;
    }

    /** The floor of a model waypoint (0 or 1). */
    public static int floorOf(String waypoint) {
        return UPPER_FLOOR_WAYPOINTS.getOrDefault(waypoint, 0);
    }

    /** Whether a model edge is a corridor ({@code Building.adj}): it has a route and needs no door or lift opened by the building. */
    public boolean isCorridor(String src, String dst) {
        return routes.containsKey(List.of(src, dst)) && !passages.contains(List.of(src, dst));
    }

    /** The lift landing whose landing waypoint is {@code waypoint}, if any. */
    public static Optional<LiftLanding> liftLandingAt(String waypoint) {
        return LIFT_LANDINGS.stream().filter(l -> l.landing().equals(waypoint)).findFirst();
    }

    /** The landing of {@code lift} on {@code floor}. */
    public static LiftLanding liftLanding(String lift, int floor) {
        return LIFT_LANDINGS.stream().filter(l -> l.lift().equals(lift) && l.floor() == floor).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("lift '" + lift + "' has no landing on floor " + floor));
    }

    /** The controlled door between two model waypoints, if any. */
    public static Optional<String> controlledDoor(String a, String b) {
        return CONTROLLED_DOORS.stream().filter(d -> d.a().equals(a) && d.b().equals(b) || d.a().equals(b) && d.b().equals(a))
                .map(ControlledDoor::door).findFirst();
    }

    /** Whether {@code door} joins {@code a} and {@code b} (the world property {@code Building.doorway}, for every binding). */
    public static boolean isDoorway(String door, String a, String b) {
        return controlledDoor(a, b).map(door::equals).orElse(false);
    }

    /** Whether {@code waypoint} is a landing of {@code lift} (the world property {@code Building.landing}). */
    public static boolean isLanding(String lift, String waypoint) {
        return liftLandingAt(waypoint).map(l -> l.lift().equals(lift)).orElse(false);
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

    /**
     * The simulator waypoints from {@code src} to {@code dst} for a model edge, or empty if the model has no such edge. Door
     * and lift passages have routes too (the robot drives them once the building opened the door): see {@link #isCorridor}.
     */
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

    /** The model waypoint a position belongs to: the room (or lift cabin) it lies in, else the nearest corridor waypoint. */
    public String waypointAt(Vec2 p) {
        Optional<String> room = plan.roomAt(p).map(Room::name)
                .filter(r -> ROOMS.contains(r) || LIFT_LANDINGS.stream().anyMatch(l -> l.cabin().equals(r)));
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

    private static Map<String, String> orderedMap(List<String> keys, List<String> values) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < keys.size(); i++) {
            m.put(keys.get(i), values.get(i));
        }
        return Collections.unmodifiableMap(m);
    }

    private static Map<String, Vec2> orderedMap(String k1, Vec2 v1, String k2, Vec2 v2) {
        Map<String, Vec2> m = new LinkedHashMap<>();
        m.put(k1, v1);
        m.put(k2, v2);
        return Collections.unmodifiableMap(m);
    }
}
