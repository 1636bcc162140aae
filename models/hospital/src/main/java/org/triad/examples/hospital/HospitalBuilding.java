package org.triad.examples.hospital;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

import org.triad.sim.Contact;
import org.triad.sim.PersonSpec;
import org.triad.sim.Rect;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;
import org.triad.sim.SimulationClock;
import org.triad.sim.Vec2;

/**
 * The simulated hospital as one building: one dyn4j simulation of the models' floor with its people and items and
 * many couriers, each with its own {@code IRobot}/{@code IWorld} implementation ({@link Courier}) over the shared
 * world. An item one courier picked up is gone for the others; couriers meet in the corridors and block each
 * other. Each courier has a {@link org.triad.sim.Battery} ({@link HospitalObjects#courierBattery()}: 0.5 % of a full
 * charge per metre driven, the models' {@code Courier.drain()}) that charges at the dock {@value #DOCK} (500 W). The first courier starts at the lobby's waypoint (as {@link HospitalSimulation}'s), the others park
 * in one row along the walls of the lobby (17 spots, each with a clear way out: see {@link #LOBBY_SPOTS}), then in two
 * columns along the walls of ward 3, ward 2, storage, x-ray and ward 1 (24 spots a room), one room after the other in turn.
 *
 * <p>Script the building ({@code sim().at(40).closeDoor(...)}) before {@link #start(double)}; afterwards the clock
 * steps it and everything goes through {@link SimulationClock#call} or the couriers' blocking actions.
 */
public final class HospitalBuilding {
    /** The charging dock, at the lobby's waypoint: a courier standing still there charges its battery. */
    public static final String DOCK = "lobby";
    /** Rooms whose walls the couriers park along, in order of filling. */
    static final List<String> PARKING = List.of("lobby", "ward3", "ward2", "storage", "xray", "ward1");

    /** One courier of the building: its simulated robot, its model actors' implementations and its own log of reasons. */
    public record Courier(String name, Robot robot, SimulatedCourier robotActor, SimulatedBuilding worldActor, PlatformLog log) {
    }

    private final HospitalFloor floor = new HospitalFloor();
    private final HospitalObjects objects = new HospitalObjects();
    private final Simulation sim;
    private final Map<String, Courier> couriers = new LinkedHashMap<>();
    private SimulationClock clock;

    /**
     * @param seed        random seed of the people's choices
     * @param recordTrace whether to keep every frame (for pictures); a long-running building turns it off
     * @param names       the couriers' names (distinct), e.g. their VDA 5050 serial numbers
     * @throws IllegalArgumentException for no names, duplicates, or more couriers than parking spots
     */
    public HospitalBuilding(long seed, boolean recordTrace, List<String> names) {
        Objects.requireNonNull(names, "names");
        if (names.isEmpty()) {
            throw new IllegalArgumentException("a building needs at least one courier");
        }
        sim = Simulation.builder(floor.plan()).seed(seed).recordTrace(recordTrace).build();
        floor.equip(sim);
        HospitalFloor.PEOPLE.forEach((name, at) -> sim.addPerson(name, at,
                PersonSpec.defaults().withMaxSpeed(HospitalFloor.WALKING_SPEED.get(name))));
        sim.addDock(DOCK, floor.plan().waypoint(DOCK).position());
        Whereabouts whereabouts = new Whereabouts(floor);
        List<Vec2> spots = parkingSpots(floor);
        int spot = 0;
        for (int i = 0; i < names.size(); i++) {
            String name = names.get(i);
            if (couriers.containsKey(name)) {
                throw new IllegalArgumentException("duplicate courier '" + name + "'");
            }
            Robot robot = null;
            if (i == 0) {
                robot = sim.addRobot(name, HospitalFloor.ROBOT_START, HospitalObjects.courierSpec());
            }
            while (robot == null) {
                if (spot >= spots.size()) {
                    throw new IllegalArgumentException("the hospital has room for " + i + " couriers, not " + names.size());
                }
                try {
                    robot = sim.addRobot(name, spots.get(spot++), HospitalObjects.courierSpec());
                } catch (IllegalArgumentException occupied) {
                    // someone stands there: the next spot
                }
            }
            robot.setBattery(HospitalObjects.courierBattery());
            PlatformLog log = new PlatformLog();
            SimulatedCourier actor = new SimulatedCourier(floor, objects, sim, robot, whereabouts, log);
            couriers.put(name, new Courier(name, robot, actor, new SimulatedBuilding(floor, objects, sim, actor, whereabouts, log), log));
        }
    }

    /**
     * The lobby's parking spots (m), one row along its walls: the straight way from each to the lobby's waypoint (where a
     * courier leaving drives first, then out through the door) passes every other spot, Alice (at 5.6, 2.0) and the way
     * from the waypoint out through the door at least 0.68 m off, centre to centre (two couriers of radius 0.3 m touch
     * at 0.6), so a courier leaving never brushes one parked. Found by a randomized greedy search over the walls (0.4 m
     * off them, 1.2 m or more from the waypoint); {@code HospitalBuildingParkingTest} checks the property. The way out
     * through the door is kept {@value #WAY_OUT_CLEARANCE} m clear: two spots 0.7 and 0.8 m either side of it (19 spots
     * before) let a courier through on the map but not past the simulator's avoidance, and at 20 couriers every one
     * leaving stuck between them, backed off into the lobby and was touched by the next one leaving (135 contacts, no task done).
     */
    /** How far every lobby spot stands off the way from the lobby's waypoint out through its door (m, centre to the line). */
    static final double WAY_OUT_CLEARANCE = 1.0;

    static final List<Vec2> LOBBY_SPOTS = List.of(new Vec2(0.40, 1.85), new Vec2(0.40, 0.90), new Vec2(1.15, 0.40), new Vec2(2.30, 0.40),
            new Vec2(3.20, 0.40), new Vec2(4.15, 0.40), new Vec2(4.90, 0.40), new Vec2(5.85, 0.40), new Vec2(7.60, 3.25), new Vec2(7.60, 4.15),
            new Vec2(6.70, 4.60), new Vec2(5.55, 4.60), new Vec2(2.20, 4.60), new Vec2(0.95, 4.60),
            new Vec2(0.40, 4.10), new Vec2(0.40, 3.35), new Vec2(0.40, 2.60));

    /**
     * The lobby's spots, then two columns along each side wall of the other parking rooms, 0.8 m apart, clear of the
     * doors in the middle (a second column there stands in the first one's way out: only the lobby is laid out for it),
     * taken one room after the other in turn: each of those rooms is a node for one robot on the traffic map, so the
     * couriers beyond the lobby's start one to a room (ward 3, ward 2, storage, x-ray, ward 1) before any room gets a second.
     */
    static List<Vec2> parkingSpots(HospitalFloor floor) {
        List<Vec2> spots = new ArrayList<>(LOBBY_SPOTS);
        List<List<Vec2>> rooms = new ArrayList<>();
        for (String room : PARKING.subList(1, PARKING.size())) {
            Rect r = floor.plan().room(room).bounds();
            List<Vec2> inRoom = new ArrayList<>();
            double[] xs = {r.minX() + 0.6, r.maxX() - 0.6, r.minX() + 1.4, r.maxX() - 1.4};
            for (double x : xs) {
                for (double y = r.minY() + 0.6; y <= r.maxY() - 0.6 + 1e-9; y += 0.8) {
                    inRoom.add(new Vec2(x, y));
                }
            }
            rooms.add(inRoom);
        }
        for (int i = 0; rooms.stream().anyMatch(r -> !r.isEmpty()); i++) {
            List<Vec2> room = rooms.get(i % rooms.size());
            if (!room.isEmpty()) {
                spots.add(room.remove(0));
            }
        }
        return spots;
    }

    /** Starts the building's clock ({@code speed} virtual seconds per wall second, or {@link SimulationClock#AS_FAST_AS_POSSIBLE}). */
    public synchronized SimulationClock start(double speed) {
        if (clock != null) {
            throw new IllegalStateException("the building runs already");
        }
        clock = SimulationClock.start(sim, speed);
        return clock;
    }

    /** The clock, once started. */
    public synchronized java.util.Optional<SimulationClock> clock() {
        return java.util.Optional.ofNullable(clock);
    }

    /** Reports every contact between two couriers (on the clock thread; keep it short). */
    public void onContact(Consumer<Contact> listener) {
        sim.onContact(listener);
    }

    public Simulation sim() {
        return sim;
    }

    public HospitalFloor floor() {
        return floor;
    }

    public HospitalObjects objects() {
        return objects;
    }

    /** @throws IllegalArgumentException for a name that is not a courier of this building */
    public Courier courier(String name) {
        Courier c = couriers.get(name);
        if (c == null) {
            throw new IllegalArgumentException("no courier '" + name + "' in this building; couriers: " + couriers.keySet());
        }
        return c;
    }

    /** The couriers in the order given. */
    public List<Courier> couriers() {
        return Collections.unmodifiableList(new ArrayList<>(couriers.values()));
    }

    /** Stops the clock (if started). */
    public synchronized void stop() {
        if (clock != null) {
            clock.close();
        }
    }
}
