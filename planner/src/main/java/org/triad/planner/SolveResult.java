package org.triad.planner;

import java.util.Objects;

/**
 * Outcome of one planning call. {@code UNSOLVABLE} means the planner proved there is no plan
 * (exhausted its search); {@code TIMEOUT} means it gave up; {@code ERROR} carries a message.
 */
public record SolveResult(Status status, PddlPlan plan, String message, Stats stats) {
    public enum Status { SOLVED, UNSOLVABLE, TIMEOUT, ERROR }

    /** Effort figures: milliseconds spent grounding and searching, states expanded. */
    public record Stats(double groundMillis, double searchMillis, long expanded, long evaluated) {
        public static final Stats NONE = new Stats(0, 0, 0, 0);
    }

    public SolveResult {
        Objects.requireNonNull(status);
        if (status == Status.SOLVED && plan == null) throw new IllegalArgumentException("a solved result needs a plan");
        if (stats == null) stats = Stats.NONE;
        if (message == null) message = "";
    }

    public static SolveResult solved(PddlPlan plan, Stats stats) {
        return new SolveResult(Status.SOLVED, plan, "", stats);
    }

    public static SolveResult unsolvable(String why, Stats stats) {
        return new SolveResult(Status.UNSOLVABLE, null, why, stats);
    }

    public static SolveResult timeout(Stats stats) {
        return new SolveResult(Status.TIMEOUT, null, "time limit reached", stats);
    }

    public static SolveResult error(String message) {
        return new SolveResult(Status.ERROR, null, message, Stats.NONE);
    }

    public boolean isSolved() {
        return status == Status.SOLVED;
    }
}
