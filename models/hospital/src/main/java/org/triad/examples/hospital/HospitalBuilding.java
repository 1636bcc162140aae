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
 * charge per metre driven, the models' {@code Courier.drain()}) that charges at the lobby's dock (500 W; the models'
 * dock {@value #DOCK}, on the spot {@link LobbyParking#DOCK} off the way out). A courier alone starts at the lobby's
 * waypoint, as {@link HospitalSimulation}'s; of several, the first starts on the dock, the
 * next 14 on the lobby's parking spots ({@link LobbyParking}, each with a clear way out), then in two columns along the
 * walls of ward 3, ward 2, storage, x-ray and ward 1 (24 spots a room), one room after the other in turn.
 *
 * <p>Script the building ({@code sim().at(40).closeDoor(...)}) before {@link #start(double)}; afterwards the clock
 * steps it and everything goes through {@link SimulationClock#call} or the couriers' blocking actions.
 */
public final class HospitalBuilding {
    /** The models' waypoint of the charging dock: the dock stands in the lobby at {@link LobbyParking#DOCK}, where a courier standing still charges. */
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
        sim.addDock(DOCK, LobbyParking.places().get(LobbyParking.DOCK));
        Whereabouts whereabouts = new Whereabouts(floor);
        List<Vec2> spots = parkingSpots(floor);
        int spot = 0;
        for (int i = 0; i < names.size(); i++) {
            String name = names.get(i);
            if (couriers.containsKey(name)) {
                throw new IllegalArgumentException("duplicate courier '" + name + "'");
            }
            // a courier alone starts at the lobby's waypoint, as HospitalSimulation's (in nobody's way)
            Robot robot = names.size() == 1 ? sim.addRobot(name, HospitalFloor.ROBOT_START, HospitalObjects.courierSpec()) : null;
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
     * Where the couriers start, in order: the lobby's dock and parking spots ({@link LobbyParking}; 19 spots along its
     * walls before session 10, two of them 0.7 and 0.8 m either side of the way out, let a courier through on the map but
     * not past the simulator's avoidance: at 20 couriers every one leaving stuck between them, 135 contacts, no task done).
     */
    static final List<Vec2> LOBBY_SPOTS = List.copyOf(LobbyParking.places().values());

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
