package org.triad.sim;

import java.util.Locale;

/**
 * The outcome of a blocking robot activity. Times are virtual seconds since the simulation start;
 * {@code position} is the robot position (metres) when the activity ended. {@code failure} is null on success.
 */
public record ActionResult(String action, boolean success, Failure failure, String message, double startTime,
                           double endTime, Vec2 position) {

    static ActionResult ok(String action, String message, double start, double end, Vec2 pos) {
        return new ActionResult(action, true, null, message, start, end, pos);
    }

    static ActionResult fail(String action, Failure failure, String message, double start, double end, Vec2 pos) {
        return new ActionResult(action, false, failure, message, start, end, pos);
    }

    ActionResult endingAt(double end, Vec2 pos) {
        return new ActionResult(action, success, failure, message, startTime, end, pos);
    }

    /** Virtual seconds the activity took. */
    public double duration() {
        return endTime - startTime;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%s %s%s at t=%.2fs %s: %s", action, success ? "succeeded" : "FAILED",
                success ? "" : " (" + failure + ")", endTime, position, message);
    }
}
