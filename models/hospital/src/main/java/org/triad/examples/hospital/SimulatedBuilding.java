package org.triad.examples.hospital;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

import org.triad.sim.ActionResult;
import org.triad.sim.Person;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;

import generated.hospital.IWorld;
import generated.hospital.domain.Item;
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

    /** The model has the edge and the robot knows of no closed door on it. */
    @Override
    public boolean adj(WayPoint a, WayPoint b) {
        Optional<List<String>> route = floor.route(a.name(), b.name());
        if (route.isEmpty()) {
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

    /** The length of the model edge's route between two model waypoints, metres (the straight line if there is no edge). */
    public static double routeLength(HospitalFloor floor, String a, String b) {
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

    /** The item's weight, kg (its class attribute). */
    @Override
    public int weight(Item i) {
        return i.getWeight();
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
