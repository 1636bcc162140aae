package org.triad.planner;

import java.util.ArrayList;
import java.util.List;

/**
 * The engine's effort in work units: facts and operator rows the heuristics touched, operators
 * {@link Successors} considered and facts it wrote. Every budget that decides which plan is returned
 * (the improver's, the portfolio's turns, the goal agenda's) is counted in these units, never in
 * time, so the same input gives the same plan on any machine and under any load; the wall clock
 * only ends planning (the timeout). Measured with `./triad solve`-like runs in a fresh JVM (2 cores,
 * Java 17, load average 6): 13-50 million units per second of search (gripper 13, logistics 18,
 * miconic 25, elevators 32, blocks 41, depot 50), so {@link #UNITS_PER_SECOND} relates the time
 * budgets the engine once had to work.
 */
final class WorkMeter {
    /** Work units of about one second of one core (a conversion for budgets, not a timing). */
    static final long UNITS_PER_SECOND = 50_000_000L;

    private final List<FfHeuristic> heuristics = new ArrayList<>(2);
    private final Successors successors;

    WorkMeter(FfHeuristic heuristic, Successors successors) {
        heuristics.add(heuristic);
        this.successors = successors;
    }

    /** Work the heuristics added later had done before (a reused one counts only what it does from then on). */
    private long before;

    /** Counts another heuristic's work too (one the caller made for another configuration, or a reused one), from now on. */
    WorkMeter add(FfHeuristic heuristic) {
        if (!heuristics.contains(heuristic)) {
            heuristics.add(heuristic);
            before += heuristic.work();
        }
        return this;
    }

    /** Work done so far by everything measured (monotonic: budgets are differences). */
    long now() {
        long w = successors.work();
        for (FfHeuristic h : heuristics) w += h.work();
        return w - before;
    }
}
