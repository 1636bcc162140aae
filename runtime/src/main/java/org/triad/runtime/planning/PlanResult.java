package org.triad.runtime.planning;

import java.util.Objects;

/**
 * Outcome of one planning call. {@code UNSOLVABLE} means the planner proved there is no plan
 * (exhausted its search); {@code TIMEOUT} means it gave up; {@code ERROR} carries a message.
 */
public record PlanResult(Status status, Plan plan, String message, Stats stats) {
    public enum Status { SOLVED, UNSOLVABLE, TIMEOUT, ERROR }

    /** Effort figures: milliseconds spent grounding and searching, states expanded. */
    public record Stats(double groundMillis, double searchMillis, long expanded, long evaluated) {
        public static final Stats NONE = new Stats(0, 0, 0, 0);
    }

    public PlanResult {
        Objects.requireNonNull(status);
        if (status == Status.SOLVED && plan == null) throw new IllegalArgumentException("a solved result needs a plan");
        if (stats == null) stats = Stats.NONE;
        if (message == null) message = "";
    }

    public static PlanResult solved(Plan plan, Stats stats) {
        return new PlanResult(Status.SOLVED, plan, "", stats);
    }

    public static PlanResult unsolvable(String why, Stats stats) {
        return new PlanResult(Status.UNSOLVABLE, null, why, stats);
    }

    public static PlanResult timeout(Stats stats) {
        return new PlanResult(Status.TIMEOUT, null, "time limit reached", stats);
    }

    public static PlanResult error(String message) {
        return new PlanResult(Status.ERROR, null, message, Stats.NONE);
    }

    public boolean isSolved() {
        return status == Status.SOLVED;
    }
}
