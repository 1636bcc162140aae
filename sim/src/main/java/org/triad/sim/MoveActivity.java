package org.triad.sim;

import java.util.List;
import java.util.Locale;

/**
 * Drives along a polyline of waypoints: waits in front of closed doors (then fails DOOR_CLOSED),
 * fails PATH_BLOCKED after no progress, and when guiding adapts its speed to the person behind.
 */
final class MoveActivity extends Activity {
    private final PathFollower follower;
    private final String goal;
    private final Person guided;
    private double deadline;
    private double bestRemaining;
    private double lastProgress;
    private double doorWaitStart = -1;
    private double farSince = -1;

    MoveActivity(Robot robot, String action, String goal, List<Vec2> via, Person guided) {
        super(robot, action);
        this.goal = goal;
        this.guided = guided;
        this.follower = new PathFollower(robot.sim.plan(), robot.position(), via, Robot.ARRIVAL_TOLERANCE);
        double length = follower.remaining(robot.position());
        this.deadline = start + (guided == null ? 3 : 6) * length / robot.maxSpeed + 2 * robot.spec().blockedSeconds()
                + robot.spec().doorWaitSeconds() + 30;
        this.bestRemaining = length;
        this.lastProgress = start;
    }

    @Override
    void shift(double seconds) {
        deadline += seconds;
        lastProgress += seconds;
        doorWaitStart = doorWaitStart < 0 ? doorWaitStart : doorWaitStart + seconds;
        farSince = farSince < 0 ? farSince : farSince + seconds;
    }

    @Override
    Agent partner() {
        return guided;
    }

    @Override
    void control(double dt) {
        Vec2 p = robot.position();
        double now = robot.sim.time();
        if (now > deadline) {
            fail(Failure.TIMEOUT, String.format(Locale.ROOT, "did not reach '%s' within %.1f s", goal,
                    deadline - start));
            return;
        }
        double factor = 1;
        if (guided != null) {
            double gd = guided.position().distance(p);
            if (!guided.isPresent() || gd > Robot.GUIDE_WAIT_DISTANCE + 5) {
                farSince = farSince < 0 ? now : farSince;
                if (!guided.isPresent() || now - farSince > Robot.LOST_SECONDS) {
                    fail(Failure.PERSON_LOST, String.format(Locale.ROOT, "person '%s' is %.1f m away",
                            guided.name(), gd));
                    return;
                }
            } else {
                farSince = -1;
            }
            factor = gd > Robot.GUIDE_WAIT_DISTANCE ? 0 : gd > Robot.GUIDE_DISTANCE + 0.8
                    ? (Robot.GUIDE_WAIT_DISTANCE - gd) / (Robot.GUIDE_WAIT_DISTANCE - Robot.GUIDE_DISTANCE - 0.8) : 1;
        }
        if (follower.arrived(p) && robot.velocity().length() < 0.15) {
            if (guided == null || guided.position().distance(p) <= Robot.GUIDE_ARRIVAL_RADIUS) {
                succeed("arrived at '" + goal + "'" + (guided == null ? "" : String.format(Locale.ROOT,
                        " with '%s' %.2f m away", guided.name(), guided.position().distance(p))));
                return;
            }
            robot.drive(Vec2.ZERO, dt);
            lastProgress = now;
            return;
        }
        Door closed = follower.closedDoorAhead(p, Robot.DOOR_SENSE_RANGE, robot.sim);
        if (closed != null) {
            robot.noteClosedDoor(closed.name());
            if (doorWaitStart < 0 && robot.velocity().length() < 0.05) {
                doorWaitStart = now;
            }
            if (doorWaitStart >= 0 && now - doorWaitStart >= robot.spec().doorWaitSeconds()) {
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
        } else if (now - lastProgress > robot.spec().blockedSeconds()) {
            fail(Failure.PATH_BLOCKED, String.format(Locale.ROOT,
                    "no progress towards '%s' for %.1f s; obstructed near %s by %s", goal, now - lastProgress, p,
                    robot.sim.peopleNear(p, robot.radius + 1.0)));
            return;
        }
        robot.drive(robot.avoid(follower.desiredVelocity(p, robot.maxSpeed * factor, robot.maxAcceleration), guided), dt);
    }

    /** Creeps towards a closed door, stopping close enough to open it. */
    private void approachDoor(Vec2 p, Door d, double dt) {
        double gap = Segments.pointDistance(p, d.doorway().end1(), d.doorway().end2()) - robot.radius - 0.35;
        Vec2 desired = follower.desiredVelocity(p, robot.maxSpeed, robot.maxAcceleration);
        double v = Math.min(desired.length(), Math.sqrt(2 * 0.9 * robot.maxAcceleration * Math.max(0, gap)));
        robot.drive(robot.avoid(desired.normalized().times(v), guided), dt);
    }
}
