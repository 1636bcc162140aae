package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.sim.Vec2;

/**
 * The lobby's parking spots and its charging dock as places of their own: finer than the models' one waypoint
 * {@value #HALL}, which stays the hall's centre that every courier passes on its way in and out (and what the planner
 * means by {@code lobby}). Each spot and the dock is a simulator waypoint joined to the centre by a straight lane, a
 * node and a lane of the traffic map, and a node id a simulated AGV reports and drives to; what the models see of a
 * courier on any of them is {@code lobby} ({@link #waypointOf}).
 *
 * <p>The positions: one row along the lobby's walls (15 of 17), found by a randomized greedy search (0.4 m off the walls, 1.2 m or
 * more from the centre) so that the straight way from each to the centre passes every other one and Alice (at 5.6, 2.0)
 * at least 0.68 m off centre to centre (two couriers of radius 0.3 m touch at 0.6), and each stands
 * {@value #WAY_OUT_CLEARANCE} m or more off the way from the centre out through the door: a courier leaving never brushes
 * one parked ({@code HospitalBuildingParkingTest}). The dock is the one straight south of the centre: a courier charging
 * there is off everyone's way out (it stood on the centre before, and couriers leaving drove into it).
 */
public final class LobbyParking {
    /** The models' waypoint of the lobby: on the traffic map the hall's centre, passed by everyone, where nobody parks. */
    public static final String HALL = "lobby";
    /** The charging dock's node. */
    public static final String DOCK = "lobby.dock";
    /** How far every place stands off the way from the centre out through the door (m, centre to the line). */
    public static final double WAY_OUT_CLEARANCE = 1.0;
    /** How near (m) a courier must stand to a place's position to be on it. */
    static final double ON_PLACE = 0.35;

    /**
     * The dock first, then the spots: session 10's 17 positions less the two beside the dock (0.95 and 0.75 m from it). A
     * courier arriving at a place 0.75 m from a parked one stopped short of it (the simulator's avoidance stops for anyone
     * ahead within 0.75 m to the side and 0.25 m of gap: courier-3 could not reach the dock beside courier-7, four times
     * in a row), which leaving never showed, as nobody drove to a spot before they were nodes. Nobody stands within
     * {@value #APART} m of the dock now; for the spots, see {@link #besideTaken}.
     */
    private static final List<Vec2> POSITIONS = List.of(new Vec2(4.15, 0.40),
            new Vec2(0.40, 1.85), new Vec2(0.40, 0.90), new Vec2(1.15, 0.40), new Vec2(2.30, 0.40), new Vec2(5.85, 0.40),
            new Vec2(7.60, 3.25), new Vec2(7.60, 4.15), new Vec2(6.70, 4.60), new Vec2(5.55, 4.60), new Vec2(2.20, 4.60),
            new Vec2(0.95, 4.60), new Vec2(0.40, 4.10), new Vec2(0.40, 3.35), new Vec2(0.40, 2.60));
    private static final int DOCK_INDEX = 0;
    /** How far apart (m, centre to centre) a courier arriving at a place needs the next parked one (see {@link #POSITIONS}). */
    public static final double APART = 1.1;
    private static final Map<String, Vec2> PLACES = build();

    private LobbyParking() {
    }

    private static Map<String, Vec2> build() {
        Map<String, Vec2> m = new LinkedHashMap<>();
        m.put(DOCK, POSITIONS.get(DOCK_INDEX));
        int k = 1;
        for (int i = 0; i < POSITIONS.size(); i++) {
            if (i != DOCK_INDEX) {
                m.put(HALL + "." + k++, POSITIONS.get(i));
            }
        }
        return Collections.unmodifiableMap(m);
    }

    /** The dock, then the spots ({@code lobby.1} to {@code lobby.14}), with their positions (m). */
    public static Map<String, Vec2> places() {
        return PLACES;
    }

    /** The parking spots (not the dock), in order of filling. */
    public static List<String> spots() {
        return new ArrayList<>(PLACES.keySet()).subList(1, PLACES.size());
    }

    /** Whether the node is a parking spot or the dock. */
    public static boolean isPlace(String node) {
        return node != null && PLACES.containsKey(node);
    }

    /** The models' waypoint of a node: {@code lobby} for a spot or the dock, the node itself otherwise. */
    public static String waypointOf(String node) {
        return isPlace(node) ? HALL : node;
    }

    /** Whether another of the lobby's places within {@value #APART} m of {@code place} is taken: a courier would stop short of it. */
    public static boolean besideTaken(String place, java.util.function.Predicate<String> taken) {
        Vec2 p = PLACES.get(place);
        return PLACES.entrySet().stream().anyMatch(e -> !e.getKey().equals(place) && e.getValue().distance(p) < APART && taken.test(e.getKey()));
    }

    /** The spot or dock a position stands on, if any. */
    public static Optional<String> placeAt(Vec2 p) {
        return PLACES.entrySet().stream().filter(e -> e.getValue().distance(p) <= ON_PLACE).map(Map.Entry::getKey).findFirst();
    }
}
