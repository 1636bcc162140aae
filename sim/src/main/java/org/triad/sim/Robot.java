package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;

/**
 * A disc-shaped holonomic mobile robot. Its activities are blocking: each call advances virtual time
 * (stepping the whole simulation) until the activity succeeds or fails, and returns an
 * {@link ActionResult} with the reason. Calls are not re-entrant: do not call them from scripted events.
 * Positions are metres, speeds m/s, durations virtual seconds.
 *
 * <p>The robot remembers doors it has seen closed (in line of sight within {@value #DOOR_SENSE_RANGE} m) until it sees
 * them open again, and plans routes around them; so after a move fails with
 * {@link Failure#DOOR_CLOSED}, moving again to the same waypoint takes another route if the graph has one.
 */
public final class Robot extends Agent {
    /** Distance, metres, up to which the robot perceives the state of a door it has in line of sight. */
    public static final double DOOR_SENSE_RANGE = 3.0;
    private static final double ARRIVAL_TOLERANCE = 0.08;
    private static final double GUIDE_DISTANCE = 1.0;
    private static final double GUIDE_ARRIVAL_RADIUS = 2.0;
    private static final double GUIDE_WAIT_DISTANCE = 3.0;
    private static final double LOST_SECONDS = 10;

    private final RobotSpec spec;
    private final List<Item> carried = new ArrayList<>();
    private final Set<String> knownClosedDoors = new TreeSet<>();
    private Activity activity;
    private double heading;
    private Vec2 intendedDirection = Vec2.ZERO;

    Robot(Simulation sim, String name, RobotSpec spec) {
        super(sim, name, spec.radius(), spec.maxSpeed(), spec.maxAcceleration());
        this.spec = spec;
    }

    public RobotSpec spec() {
        return spec;
    }

    /** Direction of travel, radians counter-clockwise from +x (kept while standing). */
    public double heading() {
        return heading;
    }

    /** The room the robot is in, if any. */
    public Optional<Room> room() {
        return sim.plan().roomAt(position());
    }

    /** The waypoint closest to the robot. */
    public Waypoint nearestWaypoint() {
        return sim.plan().nearestWaypoint(position());
    }

    /** Whether the robot is within {@code tolerance} metres of the named waypoint. */
    public boolean isAt(String waypoint, double tolerance) {
        Checks.nonNegative("tolerance (m)", tolerance);
        return position().distance(sim.plan().waypoint(waypoint).position()) <= tolerance;
    }

    /** Items being carried, in pick order. */
    public List<Item> carried() {
        return Collections.unmodifiableList(new ArrayList<>(carried));
    }

    /** Doors the robot has seen closed and not yet seen open again (sorted by name). */
    public Set<String> knownClosedDoors() {
        return Collections.unmodifiableSet(new TreeSet<>(knownClosedDoors));
    }

    /** Forgets seen-closed doors, so the next route may try them again. */
    public void forgetClosedDoors() {
        knownClosedDoors.clear();
    }

    /**
     * Drives along the shortest route of the waypoint graph (avoiding doors known to be closed) to the
     * waypoint. Fails with DOOR_CLOSED, PATH_BLOCKED, NO_ROUTE or TIMEOUT.
     *
     * @throws IllegalArgumentException for an unknown waypoint
     */
    public ActionResult moveTo(String waypoint) {
        sim.plan().waypoint(waypoint);
        return run(routeMove("moveTo(" + waypoint + ")", waypoint, null));
    }

    /**
     * Drives straight through the listed waypoints in order (consecutive ones must be joined by a graph edge).
     *
     * @throws IllegalArgumentException for an empty list, unknown waypoints or missing edges
     */
    public ActionResult moveAlong(List<String> waypoints) {
        Checks.notNull("waypoints", waypoints);
        if (waypoints.isEmpty()) {
            throw new IllegalArgumentException("moveAlong needs at least one waypoint");
        }
        List<Vec2> via = new ArrayList<>();
        for (int i = 0; i < waypoints.size(); i++) {
            via.add(sim.plan().waypoint(waypoints.get(i)).position());
            if (i > 0 && sim.plan().edge(waypoints.get(i - 1), waypoints.get(i)).isEmpty()) {
                throw new IllegalArgumentException("no edge between waypoints '" + waypoints.get(i - 1) + "' and '"
                        + waypoints.get(i) + "'");
            }
        }
        return run(new Move("moveAlong" + waypoints, waypoints.get(waypoints.size() - 1), via, null));
    }

    /**
     * Leads a person to the waypoint: the person walks behind the robot ({@value #GUIDE_DISTANCE} m); the
     * robot waits when the person falls more than {@value #GUIDE_WAIT_DISTANCE} m behind, and succeeds when
     * it has arrived with the person within {@value #GUIDE_ARRIVAL_RADIUS} m. The person stands still afterwards.
     *
     * @throws IllegalArgumentException for an unknown person or waypoint
     */
    public ActionResult guide(String person, String waypoint) {
        Person p = sim.person(person);
        sim.plan().waypoint(waypoint);
        p.follow(this, GUIDE_DISTANCE);
        try {
            return run(routeMove("guide(" + person + ", " + waypoint + ")", waypoint, p));
        } finally {
            p.standStill();
        }
    }

    /**
     * Follows a walking person, keeping between {@code minDistance} and {@code maxDistance} metres behind
     * along the person's trail. Succeeds when the person has stopped walking and is within
     * {@code maxDistance}; fails with PERSON_LOST if the person is more than {@code maxDistance + 3} m away
     * for {@value #LOST_SECONDS} s, or TIMEOUT after {@code timeoutSeconds}.
     *
     * @throws IllegalArgumentException for an unknown person or an invalid band or timeout
     */
    public ActionResult follow(String person, double minDistance, double maxDistance, double timeoutSeconds) {
        Person p = sim.person(person);
        Checks.positive("min distance (m)", minDistance);
        Checks.positive("max distance (m)", maxDistance);
        Checks.positive("timeout (s)", timeoutSeconds);
        if (minDistance >= maxDistance) {
            throw new IllegalArgumentException("min distance " + minDistance + " m must be < max distance "
                    + maxDistance + " m");
        }
        return run(new FollowPerson(p, minDistance, maxDistance, timeoutSeconds));
    }

    /**
     * Picks the item; the robot centre must be within {@link RobotSpec#reach()} of it. Takes
     * {@link RobotSpec#handlingSeconds()}.
     *
     * @throws IllegalArgumentException for an unknown item
     */
    public ActionResult pick(String item) {
        Item it = sim.item(item);
        String action = "pick(" + item + ")";
        return run(new Handle(action, () -> {
            if (it.isRemoved() || it.holder().isPresent()) {
                return new Problem(Failure.ITEM_UNAVAILABLE, "item '" + item + "' is "
                        + (it.isRemoved() ? "gone" : "held by " + it.holder().get().name()));
            }
            double d = it.position().distance(position());
            if (d > spec.reach()) {
                return new Problem(Failure.OUT_OF_REACH, String.format(Locale.ROOT,
                        "item '%s' is %.2f m away, reach is %.2f m", item, d, spec.reach()));
            }
            if (carried.size() >= spec.capacity()) {
                return new Problem(Failure.CAPACITY_EXCEEDED, "already carrying " + carried.size() + " item(s)");
            }
            return null;
        }, () -> {
            carried.add(it);
            it.pickedBy(this);
            return "picked '" + item + "'";
        }));
    }

    /**
     * Places a carried item at the robot's position. Takes {@link RobotSpec#handlingSeconds()}.
     *
     * @throws IllegalArgumentException for an unknown item
     */
    public ActionResult place(String item) {
        Item it = sim.item(item);
        return run(new Handle("place(" + item + ")", () -> carried.contains(it) ? null
                : new Problem(Failure.NOT_CARRYING, "not carrying item '" + item + "'"), () -> {
                    carried.remove(it);
                    it.placeAt(position());
                    return "placed '" + item + "' in " + it.room().map(Room::name).orElse("no room");
                }));
    }

    /**
     * Opens the door; the robot centre must be within reach + radius of the door centre.
     *
     * @throws IllegalArgumentException for an unknown door
     */
    public ActionResult openDoor(String door) {
        Door d = sim.door(door);
        return run(new Handle("openDoor(" + door + ")", () -> {
            if (d.isLocked()) {
                return new Problem(Failure.DOOR_LOCKED, "door '" + door + "' is locked");
            }
            return doorReach(d);
        }, () -> {
            d.open();
            knownClosedDoors.remove(door);
            return "opened '" + door + "'";
        }));
    }

    /**
     * Closes the door (waits until the doorway is clear); the robot must be within reach + radius of it.
     *
     * @throws IllegalArgumentException for an unknown door
     */
    public ActionResult closeDoor(String door) {
        Door d = sim.door(door);
        return run(new Handle("closeDoor(" + door + ")", () -> doorReach(d), () -> {
            d.requestClose();
            return "closing '" + door + "'";
        }));
    }

    /**
     * Stands still for the given virtual time.
     *
     * @throws IllegalArgumentException for a negative or non-finite duration
     */
    public ActionResult waitFor(double seconds) {
        Checks.nonNegative("wait (s)", seconds);
        return run(new Handle("wait", seconds, () -> null, () -> "waited"));
    }

    private Problem doorReach(Door d) {
        double dist = Segments.pointDistance(position(), d.doorway().end1(), d.doorway().end2());
        double reach = spec.reach() + radius;
        return dist <= reach ? null : new Problem(Failure.OUT_OF_REACH,
                String.format(Locale.ROOT, "door '%s' is %.2f m away, reach is %.2f m", d.name(), dist, reach));
    }

    private Activity routeMove(String action, String goal, Person guided) {
        Optional<List<String>> route = sim.planner().route(position(), goal, knownClosedDoors, radius);
        if (route.isEmpty()) {
            return new Failed(action, Failure.NO_ROUTE, "no route to '" + goal + "' avoiding doors seen closed "
                    + knownClosedDoors);
        }
        List<Vec2> via = new ArrayList<>();
        route.get().forEach(n -> via.add(sim.plan().waypoint(n).position()));
        return new Move(action + " via " + route.get(), goal, via, guided);
    }

    private ActionResult run(Activity a) {
        if (activity != null) {
            throw new IllegalStateException("robot '" + name + "' is busy with " + activity.action);
        }
        sim.requireNotStepping();
        activity = a;
        try {
            while (a.result == null) {
                sim.step();
            }
        } finally {
            activity = null;
        }
        ActionResult r = a.result.endingAt(sim.time(), position());
        sim.record(new TraceEvent(r.endTime(), name, r.action(), r.position(), r.success(),
                r.success() ? r.message() : r.failure() + ": " + r.message()));
        return r;
    }

    void dropSilently(Item item) {
        carried.remove(item);
    }

    @Override
    void control(double dt) {
        Vec2 p = position();
        for (Door d : sim.doors()) {
            if (d.doorway().center().distance(p) <= DOOR_SENSE_RANGE && sim.plan().isClear(p, d.doorway().center(), 0)) {
                if (d.isOpen()) {
                    knownClosedDoors.remove(d.name());
                } else {
                    knownClosedDoors.add(d.name());
                }
            }
        }
        intendedDirection = Vec2.ZERO;
        if (activity != null && activity.result == null) {
            activity.control(dt);
        } else {
            drive(Vec2.ZERO, dt);
        }
    }

    /** Unit direction the controller wants to go this step (before avoidance), or zero when not moving on. */
    Vec2 intendedDirection() {
        return intendedDirection;
    }

    /** The person being guided or followed, who must not step out of the robot's way. */
    Agent partner() {
        return activity == null ? null : activity.partner();
    }

    private Vec2 avoid(Vec2 desired, Agent partner) {
        intendedDirection = desired.normalized();
        return Steering.avoid(this, desired, sim.agents(), partner, false).velocity();
    }

    @Override
    void afterStep() {
        super.afterStep();
        Vec2 v = velocity();
        if (v.length() > 0.05) {
            heading = Math.atan2(v.y(), v.x());
        }
    }

    /** Why a handling activity cannot proceed. */
    private record Problem(Failure failure, String message) {
    }

    private abstract class Activity {
        final String action;
        final double start = sim.time();
        ActionResult result;

        Activity(String action) {
            this.action = action;
        }

        void succeed(String message) {
            result = ActionResult.ok(action, message, start, sim.time(), position());
        }

        void fail(Failure f, String message) {
            result = ActionResult.fail(action, f, message, start, sim.time(), position());
        }

        abstract void control(double dt);

        Agent partner() {
            return null;
        }
    }

    private final class Failed extends Activity {
        Failed(String action, Failure f, String message) {
            super(action);
            fail(f, message);
        }

        @Override
        void control(double dt) {
            drive(Vec2.ZERO, dt);
        }
    }

    private final class Move extends Activity {
        private final PathFollower follower;
        private final String goal;
        private final Person guided;
        private final double deadline;
        private double bestRemaining;
        private double lastProgress;
        private double doorWaitStart = -1;
        private double farSince = -1;

        Move(String action, String goal, List<Vec2> via, Person guided) {
            super(action);
            this.goal = goal;
            this.guided = guided;
            this.follower = new PathFollower(sim.plan(), position(), via, ARRIVAL_TOLERANCE);
            double length = follower.remaining(position());
            this.deadline = start + (guided == null ? 3 : 6) * length / maxSpeed + 2 * spec.blockedSeconds()
                    + spec.doorWaitSeconds() + 30;
            this.bestRemaining = length;
            this.lastProgress = start;
        }

        @Override
        Agent partner() {
            return guided;
        }

        @Override
        void control(double dt) {
            Vec2 p = position();
            double now = sim.time();
            if (now > deadline) {
                fail(Failure.TIMEOUT, String.format(Locale.ROOT, "did not reach '%s' within %.1f s", goal,
                        deadline - start));
                return;
            }
            double factor = 1;
            if (guided != null) {
                double gd = guided.position().distance(p);
                if (!guided.isPresent() || gd > GUIDE_WAIT_DISTANCE + 5) {
                    farSince = farSince < 0 ? now : farSince;
                    if (!guided.isPresent() || now - farSince > LOST_SECONDS) {
                        fail(Failure.PERSON_LOST, String.format(Locale.ROOT, "person '%s' is %.1f m away",
                                guided.name(), gd));
                        return;
                    }
                } else {
                    farSince = -1;
                }
                factor = gd > GUIDE_WAIT_DISTANCE ? 0 : gd > GUIDE_DISTANCE + 0.8
                        ? (GUIDE_WAIT_DISTANCE - gd) / (GUIDE_WAIT_DISTANCE - GUIDE_DISTANCE - 0.8) : 1;
            }
            if (follower.arrived(p) && velocity().length() < 0.15) {
                if (guided == null || guided.position().distance(p) <= GUIDE_ARRIVAL_RADIUS) {
                    succeed("arrived at '" + goal + "'" + (guided == null ? "" : String.format(Locale.ROOT,
                            " with '%s' %.2f m away", guided.name(), guided.position().distance(p))));
                    return;
                }
                drive(Vec2.ZERO, dt);
                lastProgress = now;
                return;
            }
            Door closed = follower.closedDoorAhead(p, DOOR_SENSE_RANGE, sim);
            if (closed != null) {
                knownClosedDoors.add(closed.name());
                if (doorWaitStart < 0 && velocity().length() < 0.05) {
                    doorWaitStart = now;
                }
                if (doorWaitStart >= 0 && now - doorWaitStart >= spec.doorWaitSeconds()) {
                    fail(Failure.DOOR_CLOSED, String.format(Locale.ROOT,
                            "door '%s' on the route to '%s' stayed closed for %.1f s while waiting in front of it",
                            closed.name(), goal,
                            now - doorWaitStart));
                    return;
                }
                approachDoor(p, closed, dt);
                lastProgress = now;
                return;
            }
            doorWaitStart = -1;
            double remaining = follower.remaining(p);
            if (remaining < bestRemaining - 0.1 || factor == 0) {
                bestRemaining = Math.min(bestRemaining, remaining);
                lastProgress = now;
            } else if (now - lastProgress > spec.blockedSeconds()) {
                fail(Failure.PATH_BLOCKED, String.format(Locale.ROOT,
                        "no progress towards '%s' for %.1f s; obstructed near %s by %s", goal, now - lastProgress, p,
                        sim.peopleNear(p, radius + 1.0)));
                return;
            }
            drive(avoid(follower.desiredVelocity(p, maxSpeed * factor, maxAcceleration), guided), dt);
        }

        /** Creeps towards a closed door, stopping close enough to open it. */
        private void approachDoor(Vec2 p, Door d, double dt) {
            double gap = Segments.pointDistance(p, d.doorway().end1(), d.doorway().end2()) - radius - 0.35;
            Vec2 desired = follower.desiredVelocity(p, maxSpeed, maxAcceleration);
            double v = Math.min(desired.length(), Math.sqrt(2 * 0.9 * maxAcceleration * Math.max(0, gap)));
            drive(desired.normalized().times(v), dt);
        }
    }

    private final class FollowPerson extends Activity {
        private final Person person;
        private final TrailFollower follower;
        private final double min;
        private final double max;
        private final double deadline;
        private double farSince = -1;

        FollowPerson(Person person, double min, double max, double timeout) {
            super("follow(" + person.name() + ")");
            this.person = person;
            this.follower = new TrailFollower(Robot.this, person);
            this.min = min;
            this.max = max;
            this.deadline = start + timeout;
        }

        @Override
        Agent partner() {
            return person;
        }

        @Override
        void control(double dt) {
            double now = sim.time();
            double d = person.position().distance(position());
            if (!person.isPresent()) {
                fail(Failure.PERSON_LOST, "person '" + person.name() + "' left");
                return;
            }
            if (!person.isWalking() && d <= max) {
                succeed(String.format(Locale.ROOT, "'%s' stopped %.2f m away", person.name(), d));
                return;
            }
            if (now > deadline) {
                fail(Failure.TIMEOUT, String.format(Locale.ROOT, "still following '%s' after %.1f s", person.name(),
                        now - start));
                return;
            }
            if (d > max + 3) {
                farSince = farSince < 0 ? now : farSince;
                if (now - farSince > LOST_SECONDS) {
                    fail(Failure.PERSON_LOST, String.format(Locale.ROOT, "person '%s' is %.1f m away", person.name(), d));
                    return;
                }
            } else {
                farSince = -1;
            }
            drive(avoid(follower.desiredVelocity((min + max) / 2, min), person), dt);
        }
    }

    private final class Handle extends Activity {
        private final Supplier<Problem> check;
        private final Supplier<String> effect;
        private final double end;

        Handle(String action, Supplier<Problem> check, Supplier<String> effect) {
            this(action, spec.handlingSeconds(), check, effect);
        }

        Handle(String action, double seconds, Supplier<Problem> check,
               Supplier<String> effect) {
            super(action);
            this.check = check;
            this.effect = effect;
            this.end = start + seconds;
            failIfNot();
        }

        private boolean failIfNot() {
            Problem problem = check.get();
            if (problem != null) {
                fail(problem.failure(), problem.message());
                return true;
            }
            return false;
        }

        @Override
        void control(double dt) {
            drive(Vec2.ZERO, dt);
            if (sim.time() + 1e-9 >= end && !failIfNot()) {
                succeed(effect.get());
            }
        }
    }
}
