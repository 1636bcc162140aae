package org.triad.examples.hospital;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

import org.triad.sim.ActionResult;
import org.triad.sim.Person;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;

import generated.hospital.IWorld;
import generated.hospital.domain.Door;
import generated.hospital.domain.Item;
import generated.hospital.domain.Lift;
import generated.hospital.domain.Room;
import generated.hospital.domain.WayPoint;

/**
 * The robotics expert's implementation of the generated {@code IWorld} on the simulated hospital: what
 * the robot knows about the building (which corridors are passable), where items and people are, and
 * people walking while the robot follows them.
 */
public final class SimulatedBuilding implements IWorld, org.triad.runtime.app.FailureExplaining {
    /** Distance band, metres, the robot keeps behind a person it follows. */
    public static final double FOLLOW_MIN = 0.8;
    public static final double FOLLOW_MAX = 2.5;
    /** Virtual seconds a person may take to walk one corridor segment. */
    static final double WALK_TIMEOUT = 120;
    /** Simulated seconds the robot waits for the lift to stand at its floor with the door open. */
    static final double LIFT_TIMEOUT = 180;

    private final HospitalFloor floor;
    private final HospitalObjects objects;
    private final Simulation sim;
    private final SimulatedCourier courier;
    private final Whereabouts whereabouts;
    private final PlatformLog log;

    SimulatedBuilding(HospitalFloor floor, HospitalObjects objects, Simulation sim, SimulatedCourier courier,
            Whereabouts whereabouts, PlatformLog log) {
        this.floor = Objects.requireNonNull(floor, "floor");
        this.objects = Objects.requireNonNull(objects, "objects");
        this.sim = Objects.requireNonNull(sim, "sim");
        this.courier = Objects.requireNonNull(courier, "courier");
        this.whereabouts = Objects.requireNonNull(whereabouts, "whereabouts");
        this.log = Objects.requireNonNull(log, "log");
    }

    /** The model has the edge, a corridor (not a passage the building opens), and the robot knows of no closed door on it. */
    @Override
    public boolean adj(WayPoint a, WayPoint b) {
        Optional<List<String>> route = floor.route(a.name(), b.name());
        if (route.isEmpty() || !floor.isCorridor(a.name(), b.name())) {
            return false;
        }
        Robot robot = courier.robot();
        return floor.doorsOn(route.get()).stream().noneMatch(robot.knownClosedDoors()::contains);
    }

    /**
     * The length of the model edge's route, metres; between waypoints without an edge (no move plans with it) the
     * straight line.
     */
    @Override
    public double distance(WayPoint a, WayPoint b) {
        return routeLength(floor, a.name(), b.name());
    }

    /**
     * The length of the model edge's route between two model waypoints, metres (the straight line if there is no edge);
     * between two landings of one lift, what the courier drives of a ride: into the cabin at a, out of it at b.
     */
    public static double routeLength(HospitalFloor floor, String a, String b) {
        Optional<HospitalFloor.LiftLanding> from = HospitalFloor.liftLandingAt(a);
        Optional<HospitalFloor.LiftLanding> to = HospitalFloor.liftLandingAt(b);
        if (from.isPresent() && to.isPresent() && from.get().lift().equals(to.get().lift()) && from.get().floor() != to.get().floor()) {
            return routeLength(floor, a, from.get().cabin()) + routeLength(floor, to.get().cabin(), b);
        }
        List<String> route = floor.route(a, b).orElse(List.of(a, b));
        double metres = 0;
        for (int k = 1; k < route.size(); k++) {
            metres += floor.plan().waypoint(route.get(k - 1)).position().distance(floor.plan().waypoint(route.get(k)).position());
        }
        return metres;
    }

    /** Whether the simulation has a charging dock at the waypoint. */
    @Override
    public boolean dock(WayPoint w) {
        return sim.docks().containsKey(w.name());
    }

    /** The item lies (nobody carries it, nobody took it away) in the room or at the corridor waypoint. */
    @Override
    public boolean itemAt(Item i, WayPoint w) {
        org.triad.sim.Item item = sim.item(i.name());
        return !item.isRemoved() && item.holder().isEmpty() && floor.waypointAt(item.position()).equals(w.name());
    }

    @Override
    public WayPoint personAt(generated.hospital.domain.Person p) {
        Person person = sim.person(p.name());
        return objects.waypoint(whereabouts.of(p.name(), person.position()));
    }

    /** Whether the person walks their own way ({@link HospitalFloor#WALKING_AHEAD}): then followed, never guided. */
    @Override
    public boolean walksAhead(generated.hospital.domain.Person p) {
        return HospitalFloor.WALKING_AHEAD.contains(p.name());
    }

    /**
     * The person walks the model edge's route ahead of the robot, which follows within
     * [{@value #FOLLOW_MIN}, {@value #FOLLOW_MAX}] m; done when the person stands at dst with the robot behind.
     */
    @Override
    public boolean walk(generated.hospital.domain.Person p, WayPoint src, WayPoint dst) {
        String call = "walk(" + p + ", " + src + ", " + dst + ")";
        if (floor.route(src.name(), dst.name()).isEmpty()) {
            log.refused(sim.time(), call, "no corridor from " + src + " to " + dst);
            return false;
        }
        if (!courier.isFollowing(p.name())) {
            log.refused(sim.time(), call, "the robot does not follow " + p);
            return false;
        }
        Person person = sim.person(p.name());
        person.walkTo(dst.name());
        ActionResult r = courier.robot().follow(p.name(), FOLLOW_MIN, FOLLOW_MAX, WALK_TIMEOUT);
        log.add(r);
        if (!r.success()) {
            return false;
        }
        double off = person.position().distance(floor.plan().waypoint(dst.name()).position());
        if (off > HospitalFloor.AT_TOLERANCE) {
            log.refused(sim.time(), call, String.format(java.util.Locale.ROOT, "%s stopped %.2f m from %s", p, off, dst));
            return false;
        }
        whereabouts.arrived(p.name(), dst.name());
        whereabouts.arrived(courier.robot().name(), dst.name());
        return true;
    }

    @Override
    public boolean doorway(Door d, WayPoint a, WayPoint b) {
        return HospitalFloor.isDoorway(d.name(), a.name(), b.name());
    }

    @Override
    public boolean landing(Lift l, WayPoint w) {
        return HospitalFloor.isLanding(l.name(), w.name());
    }

    /**
     * The building opens the door (unless it is locked), the robot drives through, and the building closes the door
     * behind it (once the doorway is clear).
     */
    @Override
    public boolean passDoor(Door d, WayPoint src, WayPoint dst) {
        String call = "passDoor(" + d + ", " + src + ", " + dst + ")";
        if (!doorway(d, src, dst)) {
            log.refused(sim.time(), call, "door '" + d + "' does not join " + src + " and " + dst);
            return false;
        }
        String refusal = onSim(s -> {
            if (s.door(d.name()).isLocked()) {
                return "door '" + d + "' is locked";
            }
            s.openDoor(d.name());
            return null;
        });
        if (refusal != null) {
            log.refused(sim.time(), call, refusal);
            return false;
        }
        look();
        boolean through = courier.move(src, dst);
        onSim(s -> {
            s.closeDoor(d.name());
            return null;
        });
        return through;
    }

    /**
     * The lift's ride from the landing {@code src} to the landing {@code dst}: the building calls the cabin to src's floor,
     * the robot drives in, the cabin carries it to dst's floor, the robot drives out to dst. Fails with the lift's
     * reason when it stops between floors, or when it does not come within {@value #LIFT_TIMEOUT} simulated seconds.
     */
    @Override
    public boolean ride(Lift l, WayPoint src, WayPoint dst) {
        String call = "ride(" + l + ", " + src + ", " + dst + ")";
        Optional<HospitalFloor.LiftLanding> from = HospitalFloor.liftLandingAt(src.name()).filter(x -> x.lift().equals(l.name()));
        Optional<HospitalFloor.LiftLanding> to = HospitalFloor.liftLandingAt(dst.name()).filter(x -> x.lift().equals(l.name()));
        if (from.isEmpty() || to.isEmpty() || from.get().floor() == to.get().floor()) {
            log.refused(sim.time(), call, src + " and " + dst + " are not landings of lift '" + l + "' on two floors");
            return false;
        }
        if (!courier.loc().equals(src)) {
            log.refused(sim.time(), call, "the robot is at " + courier.loc() + ", not " + src);
            return false;
        }
        return callLift(call, l.name(), from.get().floor()) && look() && courier.move(src, objects.waypoint(from.get().cabin()))
                && callLift(call, l.name(), to.get().floor()) && look() && courier.move(objects.waypoint(to.get().cabin()), dst);
    }

    /** Calls the lift to the floor and waits (simulated time) until it stands there with its door open. */
    private boolean callLift(String call, String lift, int floorNumber) {
        double deadline = sim.time() + LIFT_TIMEOUT;
        while (true) {
            String[] outcome = new String[1];
            boolean there = onSim(s -> {
                org.triad.sim.Lift x = s.lift(lift);
                if (x.motion() == org.triad.sim.Lift.Motion.FAULT) {
                    outcome[0] = x.fault().orElse("lift '" + lift + "' is out of order");
                    return false;
                }
                if (x.motion() == org.triad.sim.Lift.Motion.STOPPED && x.currentFloor().equals(Optional.of(floorNumber))
                        && s.door(x.landing(floorNumber).door()).isOpen()) {
                    return true;
                }
                Optional<String> refused = s.requestLift(lift, floorNumber);
                if (refused.isPresent() && x.motion() != org.triad.sim.Lift.Motion.MOVING) {
                    outcome[0] = refused.get();
                }
                return false;
            });
            if (there) {
                return true;
            }
            if (outcome[0] != null) {
                log.failed(sim.time(), call, "LIFT_FAULT", outcome[0]);
                return false;
            }
            if (sim.time() >= deadline) {
                log.failed(sim.time(), call, "LIFT_TIMEOUT", String.format(java.util.Locale.ROOT, "lift '%s' did not come to floor %d within %.0f s",
                        lift, floorNumber, LIFT_TIMEOUT));
                return false;
            }
            courier.robot().waitFor(0.5);
        }
    }

    /** The robot stands still a moment, long enough to see a door that was opened in front of it. */
    private boolean look() {
        courier.robot().waitFor(0.3);
        return true;
    }

    /** Runs a world change on the simulation: through its clock when one steps it, else here. */
    private <T> T onSim(java.util.function.Function<Simulation, T> change) {
        Optional<org.triad.sim.SimulationClock> clock = sim.clock();
        return clock.isPresent() ? clock.get().call(change) : change.apply(sim);
    }

    @Override
    public List<Door> doors() {
        return objects.doors();
    }

    @Override
    public List<Lift> lifts() {
        return objects.lifts();
    }

    @Override
    public List<WayPoint> wayPoints() {
        return objects.corridorWaypoints();
    }

    @Override
    public List<Room> rooms() {
        return objects.rooms();
    }

    @Override
    public List<Item> items() {
        return objects.items();
    }

    @Override
    public List<generated.hospital.domain.Person> persons() {
        return objects.people();
    }

    /** The simulator's reason for the last failed action (it keeps one log for robot and world). */
    @Override
    public java.util.Optional<String> lastFailure() {
        return log.lastFailure();
    }
}
