package org.triad.examples.hospital.vda5050;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.WeakHashMap;

import org.triad.examples.hospital.LobbyParking;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * The models' moves into and out of the lobby as routes of the traffic map, which is finer there than the models'
 * waypoints ({@link LobbyParking}): a move out of {@code lobby} starts at the spot or dock the AGV reports standing on and
 * drives through the hall's centre; a move into {@code lobby} drives through the centre on to a free parking spot, so
 * nobody stays on the way out and the map knows where in the lobby each courier stands; a charge drives to the dock, a
 * node of its own that couriers queue for in the reservation table. One per traffic control (its robots' own spots).
 */
public final class LobbyRoutes {
    private static final Map<TrafficControl, LobbyRoutes> OF = Collections.synchronizedMap(new WeakHashMap<>());

    private final TrafficControl traffic;
    /** Each robot's own spot, given in the order robots first park: a robot parks there when it is free. */
    private final Map<String, String> homes = new LinkedHashMap<>();

    LobbyRoutes(TrafficControl traffic) {
        this.traffic = traffic;
    }

    /** The lobby's routes under this traffic control (one for all its robots). */
    public static LobbyRoutes of(TrafficControl traffic) {
        return OF.computeIfAbsent(traffic, LobbyRoutes::new);
    }

    /**
     * The traffic map's route for the models' edge {@code src -> dst}, for the robot whose AGV reports standing at
     * {@code at} (null: unknown): from its spot or the dock through the hall's centre when it stands on one of the
     * lobby's, on to a free spot when {@code dst} is the lobby (the centre if every spot is taken).
     */
    public List<String> route(String robot, String at, String src, String dst) {
        if (LobbyParking.spots().contains(at)) {
            synchronized (homes) { // a robot's own spot is the first it was seen parked on
                if (!homes.containsKey(robot) && !homes.containsValue(at)) {
                    homes.put(robot, at);
                }
            }
        }
        List<String> r = new ArrayList<>();
        if (at != null && !at.equals(src) && LobbyParking.isPlace(at) && LobbyParking.waypointOf(at).equals(src)) {
            r.add(at);
        }
        r.add(src);
        r.add(dst);
        if (dst.equals(LobbyParking.HALL)) {
            freeSpot(robot).ifPresent(r::add);
        }
        return r;
    }

    /** The route from where the robot stands in the lobby ({@code at}) to the dock; empty when it stands on it. */
    public List<String> toDock(String at) {
        if (LobbyParking.DOCK.equals(at)) {
            return List.of();
        }
        List<String> r = new ArrayList<>();
        if (at != null && LobbyParking.isPlace(at)) {
            r.add(at);
        }
        r.add(LobbyParking.HALL);
        r.add(LobbyParking.DOCK);
        return r;
    }

    /**
     * The way from {@code from} to a free parking spot in the lobby (fewest edges on the traffic map, through the hall's
     * centre, never through the lift), or empty when every spot is taken or there is no way.
     */
    public List<String> toParking(String robot, String from) {
        Optional<String> spot = freeSpot(robot);
        if (spot.isEmpty()) {
            return List.of();
        }
        List<String> way = traffic.read(t -> {
            org.triad.building.traffic.TrafficMap map = t.map();
            Map<String, String> previous = new LinkedHashMap<>();
            java.util.ArrayDeque<String> open = new java.util.ArrayDeque<>(List.of(from));
            previous.put(from, from);
            while (!open.isEmpty()) {
                String x = open.poll();
                if (x.equals(LobbyParking.HALL)) {
                    break;
                }
                for (String y : new java.util.TreeSet<>(map.neighbours(x))) {
                    boolean lift = map.step(x, y).stream().anyMatch(r -> r.kind() == org.triad.building.traffic.Resource.Kind.LIFT);
                    if (!lift && previous.putIfAbsent(y, x) == null) {
                        open.add(y);
                    }
                }
            }
            if (!previous.containsKey(LobbyParking.HALL)) {
                return List.of();
            }
            List<String> path = new ArrayList<>();
            for (String x = LobbyParking.HALL; !x.equals(from); x = previous.get(x)) {
                path.add(0, x);
            }
            path.add(0, from);
            return path;
        });
        if (way.isEmpty()) {
            return List.of();
        }
        List<String> r = new ArrayList<>(way);
        r.add(spot.get());
        return r;
    }

    /** The ground floor's corridor junctions (its ring): where the others pass, no place to stand idle. */
    static final java.util.Set<String> JUNCTIONS = java.util.Set.of("c0", "c1", "c2", "c3", "c4", "c5", "c6", "c7");

    /**
     * Where a robot that stands idle at {@code at} goes to be out of the others' way: a free parking spot, when {@code at} is
     * a junction of the ground floor's ring ({@link #toParking}) or the dock; empty when it may stay (in a room, on the upper
     * floor, on a spot) or has nowhere to go. Used by the fleet ({@link VdaCourier#parkOutOfTheWay}) when a task ended and by
     * the dyn4j benchmark after a failed drive: a courier resting on the ring was where the chains of waits ended, and one
     * resting on the dock after its charge kept the couriers queued for the dock waiting.
     */
    public List<String> outOfTheWay(String robot, String at) {
        if (spotApart(robot).isEmpty()) {
            return List.of();
        }
        if (LobbyParking.DOCK.equals(at)) {
            return freeSpot(robot).map(spot -> List.of(LobbyParking.DOCK, LobbyParking.HALL, spot)).orElse(List.of());
        }
        if (at == null || !JUNCTIONS.contains(at)) {
            return List.of();
        }
        List<String> route = toParking(robot, at);
        return route.size() < 2 ? List.of() : route;
    }

    /**
     * A free spot with nobody parked within {@link LobbyParking#APART} of it ({@link #freeSpot}'s first choice), or empty: a
     * courier sent to a spot between two parked ones stops short, backs off onto the hall's centre, everyone's way in and
     * out, and tries again (session 14: at 20 couriers one did so for 800 simulated seconds, touching the one beside the
     * spot every 40 s). Parking to get out of the way, or to queue for the dock, is worth it only where the courier arrives.
     */
    public Optional<String> spotApart(String robot) {
        return freeSpot(robot).filter(spot -> traffic.read(t -> !LobbyParking.besideTaken(spot, taken(t, robot))));
    }

    /**
     * Whether a place is taken for the robot: held, queued for, or on the way another robot waits to drive (its stretch and
     * horizon: session 14, a courier waiting at c0 to park on lobby.1 found couriers parked either side of it when it came,
     * and stopped short).
     */
    private static java.util.function.Predicate<String> taken(org.triad.building.traffic.ReservationTable t, String robot) {
        java.util.Set<String> headedFor = new java.util.HashSet<>();
        t.robots().stream().filter(r -> !r.equals(robot)).forEach(r -> headedFor.addAll(t.heading(r)));
        return s -> !t.needing(t.map().node(s)).isEmpty() || headedFor.contains(s);
    }

    /**
     * {@code action} (or null) along the route's models' edge {@code src -> dst}; the lanes of the lobby's parking before
     * and after it are plain drives.
     */
    public static List<RemoteAgv.EdgeAction> actions(List<String> route, String src, String dst, RemoteAgv.EdgeAction action) {
        List<RemoteAgv.EdgeAction> each = new ArrayList<>();
        for (int i = 1; i < route.size(); i++) {
            each.add(route.get(i - 1).equals(src) && route.get(i).equals(dst) ? action : null);
        }
        return each;
    }

    /**
     * Where in the lobby the robot parks now: its own spot (the first it was seen on or parked on, one robot a spot while
     * they last) if nobody holds or waits for it, else the first such spot nobody owns, then any; one with nobody parked
     * within {@link LobbyParking#APART} first; empty when every spot is taken. Own spots keep two
     * robots that park at once from choosing the same one (the second would wait for the first, parked there for good).
     */
    public Optional<String> freeSpot(String robot) {
        return traffic.read(t -> {
            synchronized (homes) {
                String home = homes.get(robot);
                // its own spot first, then those nobody owns, then the others' (their owners are elsewhere)
                List<String> order = new ArrayList<>();
                if (home != null) {
                    order.add(home);
                }
                LobbyParking.spots().stream().filter(s -> !homes.containsValue(s)).forEach(order::add);
                order.addAll(LobbyParking.spots());
                // a spot beside a taken one is the last choice: the simulator's avoidance stops a courier arriving 0.75 m
                // from a parked one short of its spot (the run that found it: four failed drives to the dock in a row)
                java.util.function.Predicate<String> taken = taken(t, robot);
                List<String> free = order.stream().filter(taken.negate()).toList();
                Optional<String> choice = free.stream().filter(s -> !LobbyParking.besideTaken(s, taken)).findFirst().or(() -> free.stream().findFirst());
                if (home == null && choice.isPresent() && !homes.containsValue(choice.get())) {
                    homes.put(robot, choice.get()); // the first spot it parks on is its own from now on
                }
                return choice;
            }
        });
    }
}
