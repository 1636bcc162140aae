package org.triad.examples.hospital.vda5050;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.building.traffic.Resource.Kind;
import org.triad.building.traffic.TrafficMap;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.LobbyParking;
import org.triad.sim.FloorPlan;
import org.triad.sim.Room;
import org.triad.sim.Vec2;

/**
 * The hospital's floor map as traffic control sees it, derived from {@link HospitalFloor}: a node per model
 * waypoint (corridor waypoints and rooms one robot; the lobby's waypoint is its hall's centre, passed by everyone, and
 * each of its parking spots and its dock is a node of its own joined to it by a lane: see {@link #LOBBY_HALL}), an edge per model edge (one lane), a door area (one robot) per door an edge passes
 * through, a corridor area (one robot) per corridor that an edge's route runs through round corners
 * (the side corridors: nobody can pass a robot there, nor wait in it), and the lift: an edge between its landings
 * (c7 and d1, the ride, driven with the edge action {@code ride}) in a lift area over it, the cabins and the passages
 * into them ({@value #LIFT_CAPACITY} robot), so that robots queue for the cabin in the order they asked.
 */
public final class HospitalTraffic {
    /**
     * Robots a corridor waypoint holds at once: one. A robot ends each model move standing on the waypoint itself,
     * so a second robot sent there is stopped by the first (PATH_BLOCKED in the building), whatever the corridor's width.
     */
    public static final int JUNCTION = 1;
    /**
     * The lobby's hall: its centre (the models' waypoint {@code lobby}, which every courier passes on its way in and out)
     * and the lanes from it to the parking spots and the dock ({@link LobbyParking}), one robot at a time, nobody waiting
     * in it; the spots and the dock are stop nodes for one robot each. Every other room holds one robot: a courier ends
     * its move on the room's waypoint, so a second one sent there is stopped by the first.
     */
    public static final String LOBBY_HALL = "lobbyHall";
    /** Robots the lift's cabin carries at once (the simulated cabin is 3 m by 3 m, but a courier drives to its centre). */
    public static final int LIFT_CAPACITY = 1;
    /** The zone of the upper floor's places (its corridor waypoints and wards): one robot fewer than it has places. */
    public static final String UPPER_FLOOR = "floor1";
    /** The zone of every place out of the lobby (corridors, rooms, the lift, the upper floor): see {@link #ADMITTED}. */
    public static final String OUT_OF_THE_LOBBY = "outOfTheLobby";
    /**
     * Robots admitted out of the lobby at once, or 0 for no limit (system property {@code traffic.admitted}; none by default):
     * the rest wait in the lobby, a hall for many, for one to come back. See {@link #map(HospitalFloor, int)}. Not on by
     * default: re-measured in session 14 (building/README.md) it gave no fewer standstills, and a number fit for 10 couriers
     * fills the lobby's spots at 20 (the rest wait there), so it would have to follow the fleet's size, which the map does not know.
     */
    public static final int ADMITTED = Integer.getInteger("traffic.admitted", 0);
    /** The prefix of the zone of a waypoint that another lane's way runs over (e.g. {@code passing-c0}). */
    public static final String PASSING = "passing-";
    /** Two couriers touch at 0.6 m between their centres: a lane passing nearer a waypoint than that passes through it. */
    private static final double ROBOT_WIDTH = 0.6;

    private HospitalTraffic() {
    }

    /** The map with {@link #ADMITTED} robots admitted out of the lobby (no limit unless the property says so). */
    public static TrafficMap map(HospitalFloor floor) {
        return map(floor, ADMITTED);
    }

    /**
     * The map; with {@code admitted > 0} a zone {@value #OUT_OF_THE_LOBBY} over every model waypoint but the lobby and the
     * lanes between them, for that many robots. The ground floor's ring has 8 places for one; with every courier out of the
     * lobby it filled (10 couriers) and only turned through refusals, and 17 or more of 20 fill every place out of it
     * (building/README.md, the dyn4j benchmark). A robot already out holds the zone, so it never waits for it (a robot in a
     * room always comes out, unlike an admission to the ring alone: session 11, 0 tasks in 20 minutes); only a robot leaving
     * the lobby waits there for it.
     */
    public static TrafficMap map(HospitalFloor floor, int admitted) {
        TrafficMap.Builder b = TrafficMap.builder();
        for (String c : HospitalFloor.CORRIDOR_WAYPOINTS) {
            b.node(c, JUNCTION);
        }
        for (String r : HospitalFloor.ROOMS) {
            b.node(r, 1);
        }
        List<String> hall = new ArrayList<>(List.of(LobbyParking.HALL));
        for (String place : LobbyParking.places().keySet()) {
            b.node(place, 1);
            b.edge(LobbyParking.HALL, place);
            hall.add(LobbyParking.HALL + "-" + place);
        }
        b.area(Kind.CORRIDOR, LOBBY_HALL, 1, hall.toArray(String[]::new));
        Map<String, List<String>> doors = new LinkedHashMap<>();
        Map<String, List<String>> corridors = new LinkedHashMap<>();
        Map<String, List<String>> passing = new LinkedHashMap<>();
        List<String> waypoints = floor.modelWaypoints();
        for (int i = 0; i < waypoints.size(); i++) {
            for (int j = i + 1; j < waypoints.size(); j++) {
                String a = waypoints.get(i);
                String z = waypoints.get(j);
                Optional<List<String>> route = floor.route(a, z);
                if (route.isEmpty()) {
                    continue;
                }
                String edge = a + "-" + z;
                b.edge(a, z);
                for (String door : floor.doorsOn(route.get())) {
                    doors.computeIfAbsent(door, k -> new ArrayList<>()).add(edge);
                }
                corridorRoundCorners(floor.plan(), route.get()).ifPresent(c -> corridors.computeIfAbsent(c, k -> new ArrayList<>()).add(edge));
                for (String w : waypoints) {
                    if (!w.equals(a) && !w.equals(z) && passes(floor.plan(), route.get(), floor.plan().waypoint(w).position())) {
                        passing.computeIfAbsent(w, k -> new ArrayList<>()).add(edge);
                    }
                }
            }
        }
        // a lane whose way runs over another waypoint (the west corridor's c1-c4 over c0, the east one's c3-c6 over the
        // lift's landing c7): a robot standing there blocks it, so the waypoint and the lane are one place for one robot,
        // a zone (the waypoint stays a stop node: robots wait there for the pharmacy's door and the lift)
        passing.forEach((w, edges) -> {
            List<String> members = new ArrayList<>(List.of(w));
            members.addAll(edges);
            b.area(Kind.ZONE, PASSING + w, 1, members.toArray(String[]::new));
        });
        // the ride: one edge between a lift's landings, driven as the AGV's edge action "ride"; it, the passages into and
        // out of the cabins and the cabins are the lift, for LIFT_CAPACITY robots, so robots queue for it in order and
        // nobody drives into a cabin another robot holds
        Map<String, List<String>> lifts = new LinkedHashMap<>();
        for (HospitalFloor.LiftLanding l : HospitalFloor.LIFT_LANDINGS) {
            List<String> members = lifts.computeIfAbsent(l.lift(), k -> new ArrayList<>());
            members.add(l.cabin());
            String passage = b.edgeIds().contains(l.landing() + "-" + l.cabin()) ? l.landing() + "-" + l.cabin() : l.cabin() + "-" + l.landing();
            members.add(passage);
            doors.remove(l.door()); // the lift's doors open with the cabin: the lift area covers them
        }
        for (int i = 0; i < HospitalFloor.LIFT_LANDINGS.size(); i++) {
            for (int j = i + 1; j < HospitalFloor.LIFT_LANDINGS.size(); j++) {
                HospitalFloor.LiftLanding x = HospitalFloor.LIFT_LANDINGS.get(i);
                HospitalFloor.LiftLanding y = HospitalFloor.LIFT_LANDINGS.get(j);
                if (x.lift().equals(y.lift())) {
                    b.edge(x.landing(), y.landing());
                    lifts.get(x.lift()).add(x.landing() + "-" + y.landing());
                }
            }
        }
        lifts.forEach((lift, members) -> b.area(Kind.LIFT, lift, LIFT_CAPACITY, members.toArray(String[]::new)));
        // the upper floor is a dead end of four places behind the lift: admitting one robot fewer keeps a place free
        // there, so that a robot in a ward can always swap with one at the corridor (see building/README.md, zones)
        List<String> upper = new ArrayList<>();
        for (String w : HospitalFloor.UPPER_FLOOR_WAYPOINTS.keySet().stream().sorted().toList()) {
            if (b.nodeIds().contains(w) && HospitalFloor.LIFT_LANDINGS.stream().noneMatch(l -> l.cabin().equals(w))) {
                upper.add(w);
            }
        }
        for (String e : b.edgeIds()) {
            String[] ends = e.split("-");
            if (ends.length == 2 && upper.contains(ends[0]) && upper.contains(ends[1])) {
                upper.add(e);
            }
        }
        long places = upper.stream().filter(b.nodeIds()::contains).count();
        b.area(Kind.ZONE, UPPER_FLOOR, (int) places - 1, upper.toArray(String[]::new));
        // the places out of the lobby: the model's corridor waypoints and rooms but the lobby (not the places in it), every
        // edge between two of them
        List<String> out = new ArrayList<>(floor.modelWaypoints().stream().filter(n -> !n.equals(HospitalFloor.ROBOT_START) && b.nodeIds().contains(n))
                .sorted().toList());
        for (String e : b.edgeIds()) {
            String[] ends = e.split("-");
            if (ends.length == 2 && out.contains(ends[0]) && out.contains(ends[1])) {
                out.add(e);
            }
        }
        if (admitted > 0) {
            b.area(Kind.ZONE, OUT_OF_THE_LOBBY, admitted, out.toArray(String[]::new));
        }
        doors.forEach((door, edges) -> b.area(Kind.DOOR, door, 1, edges.toArray(String[]::new)));
        corridors.forEach((corridor, edges) -> b.area(Kind.CORRIDOR, corridor, 1, edges.toArray(String[]::new)));
        // each lane's metres as the courier drives them (the models' distances; a ride: into the cabin and out), so that a
        // charge's reserve is measured on this map (building's ChargeReserve)
        for (String e : List.copyOf(b.edgeIds())) {
            String[] ends = e.split("-");
            if (ends.length != 2) {
                throw new IllegalStateException("edge '" + e + "' is not named after its two nodes");
            }
            b.length(e, org.triad.examples.hospital.SimulatedBuilding.routeLength(floor, ends[0], ends[1]));
        }
        return b.build();
    }

    /**
     * The doors traffic control opens and closes for the robots: every door on the map but the fire door, which
     * is closed for a reason a robot must not override (a robot facing it closed fails its move, and re-plans).
     */
    public static List<String> keptDoors(HospitalFloor floor) {
        TrafficMap map = map(floor);
        return map.resources().stream().filter(r -> r.kind() == Kind.DOOR && !r.id().equals(HospitalFloor.FIRE_DOOR)).map(r -> r.id()).toList();
    }

    /** Whether the route's way (straight between its simulator waypoints) passes within a robot's width of {@code p}. */
    private static boolean passes(FloorPlan plan, List<String> route, Vec2 p) {
        for (int i = 1; i < route.size(); i++) {
            Vec2 u = plan.waypoint(route.get(i - 1)).position();
            Vec2 v = plan.waypoint(route.get(i)).position();
            Vec2 d = v.minus(u);
            double len2 = d.dot(d);
            double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, p.minus(u).dot(d) / len2));
            if (new Vec2(u.x() + t * d.x(), u.y() + t * d.y()).distance(p) < ROBOT_WIDTH) {
                return true;
            }
        }
        return false;
    }

    /** The corridor the route's inner stretch (between its corner waypoints) runs through, if it has corners. */
    private static Optional<String> corridorRoundCorners(FloorPlan plan, List<String> route) {
        if (route.size() < 4) {
            return Optional.empty();
        }
        Vec2 p = plan.waypoint(route.get(1)).position();
        Vec2 q = plan.waypoint(route.get(route.size() - 2)).position();
        return plan.roomAt(new Vec2((p.x() + q.x()) / 2, (p.y() + q.y()) / 2)).filter(Room::corridor).map(Room::name);
    }
}
