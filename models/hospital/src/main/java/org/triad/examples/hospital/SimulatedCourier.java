package org.triad.examples.hospital;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

import org.triad.sim.ActionResult;
import org.triad.sim.Battery;
import org.triad.sim.Robot;
import org.triad.sim.Simulation;
import org.triad.sim.Vec2;

import generated.hospital.IRobot;
import generated.hospital.domain.Item;
import generated.hospital.domain.Person;
import generated.hospital.domain.WayPoint;

/**
 * The robotics expert's implementation of the generated {@code IRobot} (the paper's LogisticsRobot role)
 * on the simulated robot: each model action is one or two blocking simulator activities, and each
 * property is read off the simulation. An action returns false when the simulator reports a failure
 * (the reason goes to the {@link PlatformLog}) or when the robot is not where the action starts.
 */
public final class SimulatedCourier implements IRobot, org.triad.runtime.app.FailureExplaining {
    private final HospitalFloor floor;
    private final HospitalObjects objects;
    private final Simulation sim;
    private final Robot robot;
    private final Whereabouts whereabouts;
    private final PlatformLog log;
    private final Set<String> following = new TreeSet<>();

    SimulatedCourier(HospitalFloor floor, HospitalObjects objects, Simulation sim, Robot robot, Whereabouts whereabouts,
            PlatformLog log) {
        this.floor = Objects.requireNonNull(floor, "floor");
        this.objects = Objects.requireNonNull(objects, "objects");
        this.sim = Objects.requireNonNull(sim, "sim");
        this.robot = Objects.requireNonNull(robot, "robot");
        this.whereabouts = Objects.requireNonNull(whereabouts, "whereabouts");
        this.log = Objects.requireNonNull(log, "log");
    }

    /** The simulated robot this implementation drives. */
    public Robot robot() {
        return robot;
    }

    /** Drives the model edge's route; fails when a door on it stays closed or people block it (see {@link Robot#moveAlong}). */
    @Override
    public boolean move(WayPoint src, WayPoint dst) {
        String call = "move(" + src + ", " + dst + ")";
        Optional<List<String>> route = usableRoute(call, src, dst);
        if (route.isEmpty()) {
            return false;
        }
        return arrived(robot.moveAlong(route.get()), dst);
    }

    /**
     * Charges the battery full at the dock at {@code w}: drives the last metres onto the dock if it stands beside it,
     * then stands still while the simulation charges it. Fails (logged) where there is no dock or the battery does
     * not charge there.
     */
    @Override
    public boolean recharge(WayPoint w) {
        String call = "recharge(" + w + ")";
        if (!isAt(call, w)) {
            return false;
        }
        Vec2 dock = sim.docks().get(w.name());
        if (dock == null) {
            log.refused(sim.time(), call, "there is no charging dock at " + w + "; docks: " + sim.docks().keySet());
            return false;
        }
        // the dock may stand beside the waypoint (the lobby's, on a parking spot off the way out): onto its own waypoint
        if (dock.distance(robot.position()) > Simulation.DOCK_RANGE && !record(robot.moveTo(floor.plan().nearestWaypoint(dock).name())).success()) {
            return false;
        }
        Battery battery = robot.battery();
        for (int attempt = 0; attempt < 3 && battery.percent() < 100; attempt++) {
            double seconds = (battery.capacityJoules() - battery.energyJoules()) / Math.max(battery.chargingWatts(), 1e-9);
            if (!record(robot.waitFor(Math.min(seconds + 2 * sim.stepSeconds(), 24 * 3600))).success()) {
                return false;
            }
        }
        if (battery.percent() < 100) {
            log.refused(sim.time(), call, String.format(java.util.Locale.ROOT, "the battery does not charge at %s (%.1f %%)", w,
                    battery.percent()));
            return false;
        }
        return true;
    }

    /**
     * Drives the lane between a lobby's parking spot (or its dock) and the lobby's waypoint ({@link LobbyParking}): a place
     * finer than the models' waypoints, driven as master control's traffic map has it. False (logged) when blocked.
     */
    public boolean park(String from, String to) {
        String call = "park(" + from + ", " + to + ")";
        Optional<List<String>> route = floor.route(from, to);
        if (route.isEmpty() || !LobbyParking.isPlace(from) && !LobbyParking.isPlace(to)) {
            log.refused(sim.time(), call, "no lane of the lobby's parking from " + from + " to " + to);
            return false;
        }
        if (!loc().name().equals(LobbyParking.HALL)) {
            log.refused(sim.time(), call, "the robot is at " + loc() + ", not in the lobby");
            return false;
        }
        return record(robot.moveAlong(route.get())).success();
    }

    /** Drives straight back to a parking lane's start after the lane was blocked; false (logged) when that is blocked too. */
    public boolean parkBack(String from) {
        return record(robot.moveAlong(List.of(from))).success();
    }

    /** Picks the item; first gets within reach of it if it lies further away than the robot's reach. */
    @Override
    public boolean pick(Item i, WayPoint w) {
        String call = "pick(" + i + ", " + w + ")";
        if (!isAt(call, w)) {
            return false;
        }
        org.triad.sim.Item item = sim.item(i.name());
        if (!item.isRemoved() && item.holder().isEmpty() && item.position().distance(robot.position()) > robot.spec().reach()) {
            ActionResult approach = record(robot.approach(i.name()));
            if (!approach.success()) {
                return false;
            }
        }
        return record(robot.pick(i.name())).success();
    }

    /** Puts the item down where the robot stands. */
    @Override
    public boolean drop(Item i, WayPoint w) {
        String call = "drop(" + i + ", " + w + ")";
        if (!isAt(call, w)) {
            return false;
        }
        return record(robot.place(i.name())).success();
    }

    /** Leads the person along the model edge's route; the person walks behind and stops where the robot stops. */
    @Override
    public boolean guide(Person p, WayPoint src, WayPoint dst) {
        String call = "guide(" + p + ", " + src + ", " + dst + ")";
        Optional<List<String>> route = usableRoute(call, src, dst);
        if (route.isEmpty()) {
            return false;
        }
        // the robot's routing takes the model edge: the hospital's simulator graph has no other short route
        if (!arrived(robot.guide(p.name(), dst.name()), dst)) {
            return false;
        }
        whereabouts.arrived(p.name(), dst.name());
        return true;
    }

    /** Starts following: the robot and the person must be at the same waypoint; from now on {@code following(p)}. */
    @Override
    public boolean startFollowing(Person p, WayPoint w) {
        String call = "startFollowing(" + p + ", " + w + ")";
        if (!isAt(call, w)) {
            return false;
        }
        String personAt = whereabouts.of(p.name(), sim.person(p.name()).position());
        if (!personAt.equals(w.name())) {
            log.refused(sim.time(), call, "person '" + p + "' is at " + personAt + ", not " + w);
            return false;
        }
        following.add(p.name());
        return true;
    }

    @Override
    public WayPoint loc() {
        return objects.waypoint(whereabouts.of(robot.name(), robot.position()));
    }

    /** The simulated battery's state of charge, percent. */
    @Override
    public double battery() {
        return robot.battery().percent();
    }

    /** What a metre driven takes of the simulated battery, percent (the models' drain; {@link HospitalObjects#courierBattery()}). */
    @Override
    public double drain() {
        Battery b = robot.battery();
        return 100 * b.joulesPerMetre() / b.capacityJoules();
    }

    /** The charge a plan keeps in hand, percent ({@link HospitalObjects#RESERVE_PERCENT}). */
    @Override
    public double reserve() {
        return HospitalObjects.RESERVE_PERCENT;
    }

    /** The most it may carry, kg ({@link HospitalObjects#PAYLOAD_KG}). */
    @Override
    public int payload() {
        return HospitalObjects.PAYLOAD_KG;
    }

    @Override
    public boolean carries(Item i) {
        return robot.carried().stream().anyMatch(it -> it.name().equals(i.name()));
    }

    /** The weights of the items it carries, summed, kg. */
    @Override
    public int load() {
        return robot.carried().stream().mapToInt(it -> objects.item(it.name()).getWeight()).sum();
    }

    /**
     * The robot stopped on the way along the model edge from {@code src} to {@code dst} (blocked, timed out): drives
     * back the way it came to {@code src}, from the stretch of the edge's route it stands on, so that it stands on a
     * node again and the next move can start there (under traffic control it still holds the edge until it reports
     * {@code src}). False (logged) when the way back is blocked too; it then stands where it stopped.
     */
    public boolean backTo(WayPoint src, WayPoint dst) {
        Optional<List<String>> route = floor.route(src.name(), dst.name());
        if (route.isEmpty()) {
            log.refused(sim.time(), "backTo(" + src + ")", "no corridor from " + src + " to " + dst);
            return false;
        }
        List<String> r = route.get();
        Vec2 p = robot.position();
        int stretch = 0;
        double nearest = Double.POSITIVE_INFINITY;
        for (int i = 0; i + 1 < r.size(); i++) {
            double d = distanceToSegment(p, floor.plan().waypoint(r.get(i)).position(), floor.plan().waypoint(r.get(i + 1)).position());
            if (d < nearest) {
                nearest = d;
                stretch = i;
            }
        }
        List<String> back = new java.util.ArrayList<>(r.subList(0, stretch + 1));
        java.util.Collections.reverse(back);
        return arrived(robot.moveAlong(back), src);
    }

    private static double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
        Vec2 ab = b.minus(a);
        double len = ab.dot(ab);
        double t = len == 0 ? 0 : Math.max(0, Math.min(1, p.minus(a).dot(ab) / len));
        return p.distance(new Vec2(a.x() + t * ab.x(), a.y() + t * ab.y()));
    }

    @Override
    public boolean following(Person p) {
        return following.contains(p.name());
    }

    /** Whether the robot follows the person (for the world's walk action, which moves both). */
    boolean isFollowing(String person) {
        return following.contains(person);
    }

    /** The route of a model edge from where the robot is, or empty (logged) if it is not at src or the edge is unusable. */
    private Optional<List<String>> usableRoute(String call, WayPoint src, WayPoint dst) {
        Optional<List<String>> route = floor.route(src.name(), dst.name());
        if (route.isEmpty()) {
            log.refused(sim.time(), call, "no corridor from " + src + " to " + dst);
            return Optional.empty();
        }
        if (!isAt(call, src)) {
            return Optional.empty();
        }
        for (String door : floor.doorsOn(route.get())) {
            if (robot.knownClosedDoors().contains(door)) {
                log.refused(sim.time(), call, "door '" + door + "' on the way is closed");
                return Optional.empty();
            }
        }
        return route;
    }

    private boolean isAt(String call, WayPoint w) {
        WayPoint at = loc();
        if (!at.equals(w)) {
            log.refused(sim.time(), call, "the robot is at " + at + ", not " + w);
            return false;
        }
        return true;
    }

    private boolean arrived(ActionResult r, WayPoint dst) {
        record(r);
        if (r.success()) {
            whereabouts.arrived(robot.name(), dst.name());
        }
        return r.success();
    }

    private ActionResult record(ActionResult r) {
        log.add(r);
        return r;
    }

    /** The simulator's reason for the last failed action (it keeps one log for robot and world). */
    @Override
    public java.util.Optional<String> lastFailure() {
        return log.lastFailure();
    }
}
