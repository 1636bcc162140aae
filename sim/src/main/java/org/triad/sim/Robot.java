package org.triad.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

/**
 * A disc-shaped holonomic mobile robot. Its activities are blocking: each call advances virtual time
 * (stepping the whole simulation) until the activity succeeds or fails, and returns an
 * {@link ActionResult} with the reason. Blocking calls are not allowed from scripted events. To move
 * several robots at once, start moves with {@link #startMoveTo(String)} and await the
 * {@link PendingAction}s.
 * Positions are metres, speeds m/s, durations virtual seconds.
 *
 * <p>The robot remembers doors it has seen closed (in line of sight within {@value #DOOR_SENSE_RANGE} m) until it sees
 * them open again, and plans routes around them; so after a move fails with
 * {@link Failure#DOOR_CLOSED}, moving again to the same waypoint takes another route if the graph has one.
 */
public final class Robot extends Agent {
    /** Distance, metres, up to which the robot perceives the state of a door it has in line of sight. */
    public static final double DOOR_SENSE_RANGE = 3.0;
    static final double ARRIVAL_TOLERANCE = 0.08;
    static final double GUIDE_DISTANCE = 1.0;
    static final double GUIDE_ARRIVAL_RADIUS = 2.0;
    static final double GUIDE_WAIT_DISTANCE = 3.0;
    static final double LOST_SECONDS = 10;

    private final RobotSpec spec;
    private final List<Item> carried = new ArrayList<>();
    private final Set<String> knownClosedDoors = new TreeSet<>();
    private Activity activity;
    private PendingAction pending;
    private boolean paused;
    private Battery battery = Battery.defaults();
    private Vec2 lastPosition;
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

    void noteClosedDoor(String door) {
        knownClosedDoors.add(door);
    }

    /**
     * Pauses (true) or resumes the robot: while paused it stands still and its activity's clocks (timeouts,
     * blocked and door waits) stand still too, so it resumes where it was (VDA 5050 startPause/stopPause).
     */
    public void setPaused(boolean on) {
        sim.locked(() -> {
            if (on && !paused) {
                body.setLinearVelocity(0, 0);
            }
            paused = on;
            return null;
        });
    }

    public boolean isPaused() {
        return paused;
    }

    /** The robot's battery ({@link Battery#defaults()} unless set). */
    public Battery battery() {
        return battery;
    }

    /** Gives the robot another battery (e.g. a nearly empty one, to test what an empty battery does). */
    public void setBattery(Battery b) {
        Checks.notNull("battery", b);
        sim.locked(() -> {
            battery = b;
            return null;
        });
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
        return sim.locked(() -> {
            sim.plan().waypoint(waypoint);
            return run(routeMove("moveTo(" + waypoint + ")", waypoint, null));
        });
    }

    /**
     * Like {@link #moveTo(String)} but returns at once; the move progresses while the simulation is
     * stepped (by {@link PendingAction#await()}, {@link Simulation#step()} or another robot's blocking call).
     *
     * @throws IllegalArgumentException for an unknown waypoint
     * @throws IllegalStateException if the robot is busy with another activity
     */
    public PendingAction startMoveTo(String waypoint) {
        return sim.locked(() -> {
            sim.plan().waypoint(waypoint);
            return start(routeMove("moveTo(" + waypoint + ")", waypoint, null));
        });
    }

    /**
     * Drives straight through the listed waypoints in order (consecutive ones must be joined by a graph edge).
     *
     * @throws IllegalArgumentException for an empty list, unknown waypoints or missing edges
     */
    public ActionResult moveAlong(List<String> waypoints) {
        return sim.locked(() -> run(alongActivity(waypoints)));
    }

    /**
     * Like {@link #moveAlong(List)} but returns at once (see {@link #startMoveTo(String)}).
     *
     * @throws IllegalArgumentException for an empty list, unknown waypoints or missing edges
     * @throws IllegalStateException if the robot is busy with another activity
     */
    public PendingAction startMoveAlong(List<String> waypoints) {
        return sim.locked(() -> start(alongActivity(waypoints)));
    }

    private Activity alongActivity(List<String> waypoints) {
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
        return new MoveActivity(this, "moveAlong" + waypoints, waypoints.get(waypoints.size() - 1), via, null);
    }

    /**
     * Leads a person to the waypoint: the person walks behind the robot ({@value #GUIDE_DISTANCE} m); the
     * robot waits when the person falls more than {@value #GUIDE_WAIT_DISTANCE} m behind, and succeeds when
     * it has arrived with the person within {@value #GUIDE_ARRIVAL_RADIUS} m. The person stands still afterwards.
     * The person should start near the robot: they walk straight to the robot's trail.
     *
     * @throws IllegalArgumentException for an unknown person or waypoint
     */
    public ActionResult guide(String person, String waypoint) {
        return sim.locked(() -> {
            Person p = sim.person(person);
            sim.plan().waypoint(waypoint);
            p.follow(this, GUIDE_DISTANCE);
            try {
                return run(routeMove("guide(" + person + ", " + waypoint + ")", waypoint, p));
            } finally {
                p.standStill();
            }
        });
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
        return sim.locked(() -> {
            Person p = sim.person(person);
            Checks.positive("min distance (m)", minDistance);
            Checks.positive("max distance (m)", maxDistance);
            Checks.positive("timeout (s)", timeoutSeconds);
            if (minDistance >= maxDistance) {
                throw new IllegalArgumentException("min distance " + minDistance + " m must be < max distance "
                        + maxDistance + " m");
            }
            return run(new FollowActivity(this, p, minDistance, maxDistance, timeoutSeconds));
        });
    }

    /**
     * Drives to the waypoint nearest to the item, then straight towards it until the item is within
     * 70% of {@link RobotSpec#reach()}, so that {@link #pick(String)} can follow. Fails like
     * {@link #moveTo(String)}, or with ITEM_UNAVAILABLE for a removed or carried item.
     *
     * @throws IllegalArgumentException for an unknown item
     */
    public ActionResult approach(String item) {
        return sim.locked(() -> {
            Item it = sim.item(item);
            String action = "approach(" + item + ")";
            if (it.isRemoved() || it.holder().isPresent()) {
                return run(new Activity.Failed(this, action, Failure.ITEM_UNAVAILABLE, "item '" + item + "' is "
                        + (it.isRemoved() ? "gone" : "carried")));
            }
            Vec2 target = it.position();
            Waypoint near = sim.plan().nearestWaypoint(target);
            double d = near.position().distance(target);
            double stopShort = 0.7 * spec.reach();
            Vec2 stop = d <= stopShort ? null
                    : near.position().plus(target.minus(near.position()).times((d - stopShort) / d));
            return run(routeMove(action, near.name(), null, stop));
        });
    }

    /**
     * Picks the item; the robot centre must be within {@link RobotSpec#reach()} of it. Takes
     * {@link RobotSpec#handlingSeconds()}.
     *
     * @throws IllegalArgumentException for an unknown item
     */
    public ActionResult pick(String item) {
        return sim.locked(() -> {
            Item it = sim.item(item);
            String action = "pick(" + item + ")";
            return run(new HandlingActivity(this, action, () -> {
                if (it.isRemoved() || it.holder().isPresent()) {
                    return new HandlingActivity.Problem(Failure.ITEM_UNAVAILABLE, "item '" + item + "' is "
                            + (it.isRemoved() ? "gone" : "held by " + it.holder().get().name()));
                }
                double d = it.position().distance(position());
                if (d > spec.reach()) {
                    return new HandlingActivity.Problem(Failure.OUT_OF_REACH, String.format(Locale.ROOT,
                            "item '%s' is %.2f m away, reach is %.2f m", item, d, spec.reach()));
                }
                if (carried.size() >= spec.capacity()) {
                    return new HandlingActivity.Problem(Failure.CAPACITY_EXCEEDED, "already carrying " + carried.size() + " item(s)");
                }
                return null;
            }, () -> {
                carried.add(it);
                it.pickedBy(this);
                return "picked '" + item + "'";
            }));
        });
    }

    /**
     * Places a carried item at the robot's position. Takes {@link RobotSpec#handlingSeconds()}.
     *
     * @throws IllegalArgumentException for an unknown item
     */
    public ActionResult place(String item) {
        return sim.locked(() -> {
            Item it = sim.item(item);
            return run(new HandlingActivity(this, "place(" + item + ")", () -> carried.contains(it) ? null
                    : new HandlingActivity.Problem(Failure.NOT_CARRYING, "not carrying item '" + item + "'"), () -> {
                        carried.remove(it);
                        it.placeAt(position());
                        return "placed '" + item + "' in " + it.room().map(Room::name).orElse("no room");
                    }));
        });
    }

    /**
     * Opens the door; the robot centre must be within reach + radius of the door centre.
     *
     * @throws IllegalArgumentException for an unknown door
     */
    public ActionResult openDoor(String door) {
        return sim.locked(() -> {
            Door d = sim.door(door);
            return run(new HandlingActivity(this, "openDoor(" + door + ")", () -> {
                if (d.isLocked()) {
                    return new HandlingActivity.Problem(Failure.DOOR_LOCKED, "door '" + door + "' is locked");
                }
                return doorReach(d);
            }, () -> {
                d.open();
                knownClosedDoors.remove(door);
                return "opened '" + door + "'";
            }));
        });
    }

    /**
     * Closes the door (waits until the doorway is clear); the robot must be within reach + radius of it.
     *
     * @throws IllegalArgumentException for an unknown door
     */
    public ActionResult closeDoor(String door) {
        return sim.locked(() -> {
            Door d = sim.door(door);
            return run(new HandlingActivity(this, "closeDoor(" + door + ")", () -> doorReach(d), () -> {
                sim.closeDoor(door);
                return "closing '" + door + "'";
            }));
        });
    }

    /**
     * Stands still for the given virtual time.
     *
     * @throws IllegalArgumentException for a negative or non-finite duration
     */
    public ActionResult waitFor(double seconds) {
        return sim.locked(() -> {
            Checks.nonNegative("wait (s)", seconds);
            return run(new HandlingActivity(this, "wait", seconds, () -> null, () -> "waited"));
        });
    }

    private HandlingActivity.Problem doorReach(Door d) {
        double dist = Segments.pointDistance(position(), d.doorway().end1(), d.doorway().end2());
        double reach = spec.reach() + radius;
        return dist <= reach ? null : new HandlingActivity.Problem(Failure.OUT_OF_REACH,
                String.format(Locale.ROOT, "door '%s' is %.2f m away, reach is %.2f m", d.name(), dist, reach));
    }

    private Activity routeMove(String action, String goal, Person guided) {
        return routeMove(action, goal, guided, null);
    }

    /** A move along the graph route to {@code goal}, then straight on to {@code finalPoint} if not null. */
    private Activity routeMove(String action, String goal, Person guided, Vec2 finalPoint) {
        Optional<List<String>> route = sim.planner().route(position(), goal, knownClosedDoors, radius);
        if (route.isEmpty()) {
            return new Activity.Failed(this, action, Failure.NO_ROUTE, "no route to '" + goal
                    + "' avoiding doors seen closed " + knownClosedDoors);
        }
        List<Vec2> via = new ArrayList<>();
        route.get().forEach(n -> via.add(sim.plan().waypoint(n).position()));
        if (finalPoint != null) {
            via.add(finalPoint);
        }
        return new MoveActivity(this, action + " via " + route.get(), goal, via, guided);
    }

    private ActionResult run(Activity a) {
        sim.requireNotStepping();
        // with a clock, await releases the clock's lock (held by the public method) while the clock steps
        return start(a).await();
    }

    private PendingAction start(Activity a) {
        if (activity != null) {
            throw new IllegalStateException("robot '" + name + "' is busy with " + activity.action);
        }
        activity = a;
        pending = new PendingAction(sim);
        PendingAction p = pending;
        if (a.result != null) {
            finishActivity();
        }
        return p;
    }

    /** Closes the activity after the step in which it decided, so its end time includes that step. */
    private void finishActivity() {
        ActionResult r = activity.result.endingAt(sim.time(), position());
        activity = null;
        PendingAction p = pending;
        pending = null;
        sim.record(new TraceEvent(r.endTime(), name, r.action(), r.position(), r.success(),
                r.success() ? r.message() : r.failure() + ": " + r.message()));
        p.complete(r);
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
        if (paused) {
            if (activity != null && activity.result == null) {
                activity.shift(dt);
            }
            body.setLinearVelocity(0, 0);
            return;
        }
        if (activity != null && activity.result == null && battery.isEmpty() && activity.drives()) {
            activity.fail(Failure.BATTERY_EMPTY, String.format(Locale.ROOT, "battery empty (%.0f J/m over %.0f J) at %s",
                    battery.joulesPerMetre(), battery.capacityJoules(), p));
        }
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

    Vec2 avoid(Vec2 desired, Agent partner) {
        intendedDirection = desired.normalized();
        return Steering.avoid(this, desired, sim.agents(), partner, false).velocity();
    }

    /** The cabin carried the robot by (dx, dy) to another floor: that is no driving, and draws nothing from its battery. */
    void carried(double dx, double dy) {
        if (lastPosition != null) {
            lastPosition = new Vec2(lastPosition.x() + dx, lastPosition.y() + dy);
        }
    }

    @Override
    void afterStep() {
        super.afterStep();
        Vec2 now = position();
        if (lastPosition != null) {
            battery.drive(now.distance(lastPosition));
        }
        lastPosition = now;
        battery.dock(velocity().length() < 0.05 && sim.atDock(now), sim.stepSeconds());
        if (activity != null && activity.result != null) {
            finishActivity();
        }
        Vec2 v = velocity();
        if (v.length() > 0.05) {
            heading = Math.atan2(v.y(), v.x());
        }
    }
}
