package org.triad.planner;

/**
 * The complete search for a first plan when the goal agenda (or a bounded single-goal A*) fails:
 * three greedy configurations take turns with evaluation budgets that double every round, each
 * restarting from scratch:
 * <ol>
 * <li>LAMA's first iteration ({@link LazyGreedySearch} with the FF and landmark-count heuristics);</li>
 * <li>the same lazy search with FF only;</li>
 * <li>eager greedy best-first search on FF with a boosted preferred-operator queue.</li>
 * </ol>
 * Why not LAMA alone: where resources make states dead ends the heuristics do not see (fuel, a truck's
 * time slots), the landmark count can hold the search on a plateau that FF alone leaves quickly
 * (nomystery p07: 167 evaluations with FF alone, none within 60 s with the landmark queue added),
 * and elsewhere the reverse. Doubling budgets bound the work lost to restarts by a constant factor
 * of the best configuration's. Every configuration is complete (closed lists; only relaxed dead
 * ends are pruned), so exhausting any one proves the task unsolvable.
 */
final class FirstPlanPortfolio {
    /** Heuristic evaluations of each configuration in the first round. */
    static final long FIRST_ROUND_EVALUATIONS = 20_000;

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
        for (long budget = FIRST_ROUND_EVALUATIONS; ; budget = Math.multiplyExact(budget, 2)) {
            for (int config = 0; config < 3; config++) {
                if (System.nanoTime() > deadline) return new BestFirstSearch.Result(BestFirstSearch.Outcome.TIMEOUT, null, null, 0, 0);
                BestFirstSearch.Result r = switch (config) {
                    case 0 -> new LazyGreedySearch(heuristic, landmarks, successors, deadline).run(init, goalPos, goalNeg, budget);
                    case 1 -> new LazyGreedySearch(heuristic, null, successors, deadline).run(init, goalPos, goalNeg, budget);
                    default -> new BestFirstSearch(task, heuristic, successors, deadline).run(init, goalPos, goalNeg, 0, 1, true, budget);
                };
                effort[0] += r.expanded();
                effort[1] += r.evaluated();
                if (r.outcome() != BestFirstSearch.Outcome.LIMIT) return r;
            }
        }
    }
}
