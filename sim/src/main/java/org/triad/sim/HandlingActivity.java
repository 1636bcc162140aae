package org.triad.sim;

import java.util.function.Supplier;

/**
 * Stands still for a handling time, checking its precondition at the start and again at the end
 * (the world may change meanwhile), then applies its effect.
 */
final class HandlingActivity extends Activity {
    /** Why the activity cannot proceed. */
    record Problem(Failure failure, String message) {
    }

    private final Supplier<Problem> check;
    private final Supplier<String> effect;
    private double end;

    HandlingActivity(Robot robot, String action, Supplier<Problem> check, Supplier<String> effect) {
        this(robot, action, robot.spec().handlingSeconds(), check, effect);
    }

    HandlingActivity(Robot robot, String action, double seconds, Supplier<Problem> check, Supplier<String> effect) {
        super(robot, action);
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
    boolean drives() {
        return false;
    }

    @Override
    void shift(double seconds) {
        end += seconds;
    }

    @Override
    void control(double dt) {
        robot.drive(Vec2.ZERO, dt);
        if (robot.sim.time() + 1e-9 >= end && !failIfNot()) {
            succeed(effect.get());
        }
    }
}
