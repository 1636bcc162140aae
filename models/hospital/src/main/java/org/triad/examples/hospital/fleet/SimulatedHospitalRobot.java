package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
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
import org.triad.sim.Wall;
import org.triad.sim.Waypoint;

import generated.hospital.HospitalActionExecutor;
import generated.hospital.HospitalStateProvider;

/**
 * A courier in a hospital simulation of its own, driven by the generated StateProvider and
 * ActionExecutor. The simulation is stepped by the robot's actions; after each step this robot paces
 * virtual time against the wall clock and, every {@value #MAP_EVERY_STEPS} steps, takes a new floor map
 * on the stepping thread, so that other threads read a finished picture instead of a simulation in motion.
 */
final class SimulatedHospitalRobot implements FleetRobot {
    private static final int MAP_EVERY_STEPS = 6;
    /** After this much lag (s) pacing starts afresh instead of letting the simulation rush to catch up. */
    private static final double MAX_LAG = 0.25;

    private final String name;
    private final HospitalSimulation hospital;
    private final StateSource stateSource;
    private final ActionRunner actionRunner;
    private final double speed;
    private volatile FloorMap map;
    private long markWallNanos;
    private double markSim;

    SimulatedHospitalRobot(String name, long seed, double speed) {
        this.name = name;
        this.speed = speed;
        this.hospital = new HospitalSimulation(seed, false);
        this.stateSource = new HospitalStateProvider(hospital.courier(), hospital.building());
        this.actionRunner = new HospitalActionExecutor(hospital.courier(), hospital.building());
        Simulation sim = hospital.sim();
        map = snapshot(sim, name);
        markWallNanos = System.nanoTime();
        markSim = sim.time();
        sim.addStepListener(this::afterStep);
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

    @Override
    public Optional<FloorMap> floor() {
        return Optional.of(map);
    }

    /** The simulation, for tests and fault scenarios (script faults with {@code sim().at(t)} before tasks run). */
    HospitalSimulation hospital() {
        return hospital;
    }

    private void afterStep() {
        Simulation sim = hospital.sim();
        if (sim.steps() % MAP_EVERY_STEPS == 0) {
            map = snapshot(sim, name);
        }
        if (Double.isInfinite(speed)) {
            return;
        }
        long now = System.nanoTime();
        double due = (sim.time() - markSim) / speed - (now - markWallNanos) / 1e9;
        if (due < -MAX_LAG) {
            markWallNanos = now;
            markSim = sim.time();
        } else if (due > 0) {
            try {
                Thread.sleep((long) (due * 1000), (int) ((due * 1e9) % 1_000_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public Optional<Pose> pose() {
        return map.robots().stream().filter(m -> m.name().equals(name)).findFirst()
                .map(m -> new Pose(m.x(), m.y(), 0, org.triad.examples.hospital.vda5050.SimulatedAgv.MAP_ID));
    }

    /**
     * The hospital's floor without robots, items and people, for platforms that report where their robots
     * are but draw no map (VDA 5050 couriers): the same rooms, walls, doors and waypoints as the simulation's.
     */
    static FloorMap layout() {
        FloorMap m = snapshot(new HospitalSimulation(0, false).sim(), "");
        return new FloorMap(0, m.bounds(), m.areas(), m.walls(), m.doors(), m.waypoints(), List.of(), List.of(), List.of());
    }

    /** The floor now; the courier is labelled with its name in the fleet. */
    private static FloorMap snapshot(Simulation sim, String fleetName) {
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
            robots.add(new FloorMap.Mark(r.name().equals(HospitalSimulation.ROBOT) ? fleetName : r.name(), r.position().x(), r.position().y(),
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
