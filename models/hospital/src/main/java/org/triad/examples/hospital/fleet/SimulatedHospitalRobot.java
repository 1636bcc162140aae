package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.State;
import org.triad.runtime.app.GroundAction;
import org.triad.refarc.fleet.Battery;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.FloorMap;
import org.triad.refarc.fleet.Pose;
import org.triad.sim.Door;
import org.triad.sim.FloorPlan;
import org.triad.sim.Item;
import org.triad.sim.Person;
import org.triad.sim.Rect;
import org.triad.sim.Robot;
import org.triad.sim.Room;
import org.triad.sim.Simulation;
import org.triad.sim.SimulationClock;
import org.triad.sim.Wall;
import org.triad.sim.Waypoint;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalStateProvider;

/**
 * One courier of the service's simulated hospital ({@link SimulatedHospital}: one dyn4j simulation for the whole
 * fleet), driven by the generated StateProvider and ActionExecutor over the courier's own {@code IRobot} and
 * {@code IWorld} implementations. The building's clock steps the simulation; this robot reads its state and runs
 * its actions under the clock's lock (a blocking action releases it while it waits), so every robot sees the one
 * world as it is between two steps, and many drive at the same time.
 */
final class SimulatedHospitalRobot implements FleetRobot {
    private final String name;
    private final SimulatedHospital hospital;
    private final HospitalBuilding.Courier courier;
    private final StateSource stateSource;
    private final ActionRunner actionRunner;
    private boolean closed;

    SimulatedHospitalRobot(SimulatedHospital hospital, HospitalBuilding.Courier courier) {
        this.name = courier.name();
        this.hospital = hospital;
        this.courier = courier;
        SimulationClock clock = hospital.clock();
        HospitalStateProvider state = new HospitalStateProvider(courier.robotActor(), courier.worldActor());
        HospitalActionExecutor executor = new HospitalActionExecutor(courier.robotActor(), courier.worldActor());
        this.stateSource = () -> clock.call(s -> state.currentState());
        this.actionRunner = new ActionRunner() {
            @Override
            public Optional<String> violatedPrecondition(GroundAction action, State now) throws Exception {
                return underLock(clock, () -> executor.violatedPrecondition(action, now));
            }

            @Override
            public boolean execute(GroundAction action) throws Exception {
                return underLock(clock, () -> executor.execute(action));
            }

            @Override
            public Optional<String> failureReason(GroundAction action) {
                return clock.call(s -> executor.failureReason(action));
            }
        };
    }

    /** Runs {@code body} under the clock's lock, passing its checked exception on. */
    private static <T> T underLock(SimulationClock clock, Callable<T> body) throws Exception {
        Exception[] thrown = new Exception[1];
        T value = clock.call(s -> {
            try {
                return body.call();
            } catch (Exception e) {
                thrown[0] = e;
                return null;
            }
        });
        if (thrown[0] != null) {
            throw thrown[0];
        }
        return value;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public StateSource stateSource() {
        return stateSource;
    }

    @Override
    public ActionRunner actionRunner() {
        return actionRunner;
    }

    /** The simulation is the whole building: what this robot reports of the world is the fleet's world. */
    @Override
    public boolean observesBuilding() {
        return true;
    }

    @Override
    public Optional<FloorMap> floor() {
        return Optional.of(hospital.map());
    }

    /** One map per floor (the simulation draws both floors side by side). */
    @Override
    public java.util.Map<String, FloorMap> floors() {
        return HospitalMaps.perFloor(hospital.map());
    }

    @Override
    public Optional<Pose> pose() {
        return hospital.map().robots().stream().filter(m -> m.name().equals(name)).findFirst()
                .map(m -> new Pose(m.x(), m.y(), 0, org.triad.examples.hospital.vda5050.SimulatedAgv.mapId(HospitalFloor.floorAt(m.x()))));
    }

    @Override
    public Optional<Battery> battery() {
        org.triad.sim.Battery b = courier.robot().battery();
        return Optional.of(hospital.clock().call(s -> new Battery(b.percent(), b.isCharging())));
    }

    /** The building, for tests and fault scenarios ({@code building().clock()}). */
    HospitalBuilding building() {
        return hospital.building();
    }

    @Override
    public synchronized void close() {
        if (!closed) {
            closed = true;
            hospital.release();
        }
    }

    /**
     * The hospital's floor without robots, items and people, for platforms that report where their robots
     * are but draw no map (VDA 5050 couriers): the same rooms, walls, doors and waypoints as the simulation's.
     */
    static FloorMap layout() {
        FloorMap m = snapshot(new HospitalSimulation(0, false).sim());
        return new FloorMap(0, m.bounds(), m.areas(), m.walls(), m.doors(), m.waypoints(), List.of(), List.of(), List.of());
    }

    /** The floor now, with every robot under its name in the simulation (call it between two steps). */
    static FloorMap snapshot(Simulation sim) {
        FloorPlan plan = sim.plan();
        List<FloorMap.Area> areas = new ArrayList<>();
        for (Room r : plan.rooms()) {
            areas.add(new FloorMap.Area(r.name(), box(r.bounds()), r.corridor()));
        }
        List<FloorMap.Line> walls = new ArrayList<>();
        for (Wall w : plan.walls()) {
            walls.add(new FloorMap.Line(w.a().x(), w.a().y(), w.b().x(), w.b().y()));
        }
        List<FloorMap.Door> doors = new ArrayList<>();
        for (Door d : sim.doors()) {
            doors.add(new FloorMap.Door(d.name(), new FloorMap.Line(d.doorway().end1().x(), d.doorway().end1().y(),
                    d.doorway().end2().x(), d.doorway().end2().y()), d.isOpen()));
        }
        List<FloorMap.Mark> waypoints = new ArrayList<>();
        for (Waypoint w : plan.waypoints()) {
            if (HospitalFloor.CORRIDOR_WAYPOINTS.contains(w.name()) || HospitalFloor.ROOMS.contains(w.name())) {
                waypoints.add(new FloorMap.Mark(w.name(), w.position().x(), w.position().y(), ""));
            }
        }
        List<FloorMap.Mark> robots = new ArrayList<>();
        for (Robot r : sim.robots()) {
            robots.add(new FloorMap.Mark(r.name(), r.position().x(), r.position().y(),
                    r.carried().stream().map(Item::name).collect(Collectors.joining(", "))));
        }
        List<FloorMap.Mark> items = new ArrayList<>();
        for (Item i : sim.items()) {
            if (!i.isRemoved() && i.holder().isEmpty()) {
                items.add(new FloorMap.Mark(i.name(), i.position().x(), i.position().y(), ""));
            }
        }
        List<FloorMap.Mark> people = new ArrayList<>();
        for (Person p : sim.people()) {
            people.add(new FloorMap.Mark(p.name(), p.position().x(), p.position().y(), ""));
        }
        return new FloorMap(sim.time(), box(plan.bounds()), areas, walls, doors, waypoints, robots, items, people);
    }

    private static FloorMap.Box box(Rect r) {
        return new FloorMap.Box(r.minX(), r.minY(), r.maxX(), r.maxY());
    }
}
