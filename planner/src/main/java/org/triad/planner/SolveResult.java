package org.triad.planner;

import java.util.List;
import java.util.Objects;

/**
 * Outcome of one planning call. {@code UNSOLVABLE} means the planner proved there is no plan
 * (exhausted its search, or goal atoms are unreachable even ignoring delete effects: then
 * {@code unreachable} says why for each); {@code TIMEOUT} means it gave up; {@code ERROR} carries a message.
 */
public record SolveResult(Status status, PddlPlan plan, String message, Stats stats, List<UnreachableGoal> unreachable) {
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
        unreachable = unreachable == null ? List.of() : List.copyOf(unreachable);
    }

    public SolveResult(Status status, PddlPlan plan, String message, Stats stats) {
        this(status, plan, message, stats, List.of());
    }

    /** Unsolvable because goal atoms are unreachable even ignoring delete effects, with why. */
    public static SolveResult unreachable(String why, List<UnreachableGoal> goals, Stats stats) {
        return new SolveResult(Status.UNSOLVABLE, null, why, stats, goals);
    }

    public static SolveResult solved(PddlPlan plan, Stats stats) {
        return new SolveResult(Status.SOLVED, plan, "", stats);
    }

    /** The message of a plan returned because the timeout cut improvement short ({@link #bestSoFar()}). */
    public static final String BEST_SO_FAR = "time limit reached while improving the plan: the best plan found so far";

    /**
     * A plan found in time whose improvement the timeout cut short: valid, but perhaps longer than
     * the engine's deterministic answer (which a longer timeout gives).
     */
    public static SolveResult bestSoFar(PddlPlan plan, Stats stats) {
        return new SolveResult(Status.SOLVED, plan, BEST_SO_FAR, stats);
    }

    /** Whether this plan is the best found before the timeout ended improvement (see {@link #bestSoFar(PddlPlan, Stats)}). */
    public boolean isBestSoFar() {
        return status == Status.SOLVED && BEST_SO_FAR.equals(message);
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
