package org.triad.sim;

/** A robot activity in progress: its controller runs once per step until it sets a result. */
abstract class Activity {
    final Robot robot;
    final String action;
    final double start;
    ActionResult result;

    Activity(Robot robot, String action) {
        this.robot = robot;
        this.action = action;
        this.start = robot.sim.time();
    }

    void succeed(String message) {
        result = ActionResult.ok(action, message, start, robot.sim.time(), robot.position());
    }

    void fail(Failure f, String message) {
        result = ActionResult.fail(action, f, message, start, robot.sim.time(), robot.position());
    }

    abstract void control(double dt);

    /** Whether the activity drives the robot (an empty battery stops it). */
    boolean drives() {
        return true;
    }

    /** The robot was paused for {@code seconds}: its timers move on by as much. */
    void shift(double seconds) {
    }

    /** The person being guided or followed, if any. */
    Agent partner() {
        return null;
    }

    /** An activity that failed before it started (e.g. no route). */
    static final class Failed extends Activity {
        Failed(Robot robot, String action, Failure f, String message) {
            super(robot, action);
            fail(f, message);
        }

        @Override
        void control(double dt) {
            robot.drive(Vec2.ZERO, dt);
        }
    }
}
