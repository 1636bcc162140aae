package org.triad.planner;

/**
 * The complete search for a first plan when the goal agenda (or a bounded single-goal A*) fails:
 * four greedy configurations take turns in rounds, each round giving each of them twice the time of
 * the previous one (the first 0.5 s), each restarting from scratch:
 * <ol>
 * <li>LAMA's first iteration ({@link LazyGreedySearch} with the FF and landmark-count heuristics);</li>
 * <li>lazy greedy search with FF alone, h^add supporters ({@link AdditiveFfHeuristic}, as Fast
 *     Downward's FF);</li>
 * <li>eager greedy best-first search on FF with a boosted preferred-operator queue;</li>
 * <li>lazy greedy search with FF alone, level supporters.</li>
 * </ol>
 * Why not LAMA alone: where resources make states dead ends the heuristics do not see (fuel, a
 * truck's time slots), the landmark count can hold the search on a plateau that FF alone leaves
 * quickly (nomystery p07: 167 evaluations with FF alone, none within 60 s with the landmark queue
 * added; trucks p10: 21,000 evaluations eager), and elsewhere the reverse; where the level-first
 * relaxed plan misleads, h^add supporters do not (transport-sat11 p03). Doubling slices bound the
 * time lost to the other configurations and to restarts by a constant factor of the best
 * configuration's. Time slices, not evaluation counts, because the configurations' evaluations
 * differ up to tenfold in cost. Every configuration is complete (closed lists; only relaxed dead ends
 * are pruned), so exhausting any one proves the task unsolvable.
 */
final class FirstPlanPortfolio {
    /** Time of each configuration in the first round. */
    static final long FIRST_SLICE_NANOS = 500_000_000L;
    static final int CONFIGURATIONS = 4;

    private final SearchTask task;
    private final FfHeuristic heuristic;
    private final Successors successors;
    private final long deadline;

    FirstPlanPortfolio(SearchTask task, FfHeuristic heuristic, Successors successors, long deadlineNanos) {
        this.task = task;
        this.heuristic = heuristic;
        this.successors = successors;
        this.deadline = deadlineNanos;
    }

    /** FOUND, EXHAUSTED or TIMEOUT; {@code effort} gets the expansions and evaluations of all runs. */
    BestFirstSearch.Result run(int[] init, int[] goalPos, int[] goalNeg, long[] effort) {
        Landmarks landmarks = new Landmarks(task, init, goalPos, deadline);
        AdditiveFfHeuristic additive = null;
        for (long slice = FIRST_SLICE_NANOS; ; slice = Math.min(slice * 2, Long.MAX_VALUE / 4)) {
            for (int config = 0; config < CONFIGURATIONS; config++) {
                long now = System.nanoTime();
                if (now > deadline) return new BestFirstSearch.Result(BestFirstSearch.Outcome.TIMEOUT, null, null, 0, 0);
                long until = deadline - now > slice ? now + slice : deadline;
                if (config == 1 && additive == null) additive = new AdditiveFfHeuristic(task);
                BestFirstSearch.Result r = switch (config) {
                    case 0 -> new LazyGreedySearch(heuristic, landmarks, successors, until).run(init, goalPos, goalNeg);
                    case 1 -> new LazyGreedySearch(additive, null, successors, until).run(init, goalPos, goalNeg);
                    case 2 -> new BestFirstSearch(task, heuristic, successors, until).run(init, goalPos, goalNeg, 0, 1, true, Long.MAX_VALUE);
                    default -> new LazyGreedySearch(heuristic, null, successors, until).run(init, goalPos, goalNeg);
                };
                effort[0] += r.expanded();
                effort[1] += r.evaluated();
                if (r.outcome() != BestFirstSearch.Outcome.TIMEOUT) return r;
            }
        }
    }
}
