package org.triad.planner;

/**
 * Makes a first plan shorter within a budget of work ({@link WorkMeter}), keeping the shortest valid
 * plan found; the budget is counted in work, not time, so the plan does not depend on the machine or
 * its load, and the deadline only cuts improvement short (then {@link #timedOut()} says the plan is
 * the best found so far):
 * <ol>
 * <li>action elimination ({@link PlanShortener}) on the first plan;</li>
 * <li>when the first plan came from the goal agenda: LAMA's first iteration (lazy greedy search,
 *     FF with h^add supporters and the landmark count with disjunctive landmarks, preferred
 *     operators), which finds other plans where the agenda's goal order forces detours; where
 *     the budget ends while its FF value has come more than half way down, it goes on for the work
 *     that progress foretells, within twice the budget in all;</li>
 * <li>plan neighbourhood graph search ({@link PlanNeighbourhoodSearch}) with the smallest
 *     neighbourhood; if neither this nor the lazy search shortened the plan, the first plan is
 *     likely short already and the rest of the budget is left unused;</li>
 * <li>otherwise growing neighbourhoods for half of the remaining work where the smallest one
 *     helped, then restarts on h^add supporters (greedy, then weighted A* with weights 5, 3, 2,
 *     preferred operators) that only look for plans shorter than the best so far, until one finds
 *     none, and neighbourhoods again with what is left where either helped;</li>
 * <li>with {@link #anytime}, after the last action elimination: LAMA's later iterations (lazy weighted
 *     A* with FF and the landmark count, weights 5, 3, 2, 1, pruned at the best length) on work of
 *     their own.</li>
 * </ol>
 * Every step stops at the budget's end and is skipped once it has passed, so the budget bounds the
 * extra work (apart from one step's last heuristic evaluation). The steps use only {@link Successors}
 * to apply actions, so they follow whatever action semantics it implements.
 */
final class PlanImprover {
    /** Restarts as {g weight, h weight}: greedy, then weighted A* as in LAMA's later iterations. */
    static final int[][] RESTARTS = {{0, 1}, {1, 5}, {1, 3}, {1, 2}};
    /**
     * Plans at least this long get the lazy search on h^add supporters and disjunctive landmarks,
     * shorter ones (a robot's goal of a few steps) the cheaper set-up. Not 20: freecell 3-2's first
     * plan of 15 steps stays 15 with level supporters and becomes 14 with h^add ones (Fast Downward
     * 13); of the sample's other plans of 10-19 steps none changed.
     */
    static final int ADDITIVE_LAZY_STEPS = 10;
    /**
     * The lazy search stopped by the budget goes on when its FF value has come at least this far from
     * the initial state's towards 0 ({@link LazyGreedySearch.Run#progress()}) ...
     */
    static final double LAZY_PROGRESS_TO_EXTEND = 0.5;
    /** ... for the work its progress foretells times this margin ... */
    static final double LAZY_MARGIN = 1.25;
    /** ... as long as the whole improvement stays within this many times its budget. */
    static final long LAZY_EXTENSION = 2;
    /** Largest plan neighbourhood explored (states) ... */
    static final int NEIGHBOURHOOD_STATES = 200_000;
    /** ... and at most this many facts stored in its states, a memory bound of about 64 MB. */
    static final int NEIGHBOURHOOD_FACTS = 16_000_000;

    private final SearchTask task;
    private final FfHeuristic heuristic;
    private final Successors successors;
    private final long deadline;
    private final long[] effort;
    private final long searchEvaluations;
    private final long workBudget;
    private final WorkMeter meter;
    private long workUntil;
    /** The meter when {@link #improve} began. */
    private long improveStart;
    private boolean shortest;
    private boolean timedOut;
    private PlanNeighbourhoodSearch neighbourhood;
    private final java.util.function.Supplier<? extends FfHeuristic> additiveSource;
    private FfHeuristic additive;

    /**
     * @param deadlineNanos {@link System#nanoTime()} when improving must stop (the timeout)
     * @param effort expanded and evaluated counters to add to
     * @param searchEvaluations heuristic evaluations allowed to each search (the lazy one and every
     *     restart): where a search needs many more than the first plan did, it rarely pays off
     * @param workBudget work units ({@link WorkMeter}) improving may use
     */
    PlanImprover(SearchTask task, FfHeuristic heuristic, Successors successors, long deadlineNanos, long[] effort, long searchEvaluations,
                 long workBudget) {
        this(task, heuristic, () -> new AdditiveFfHeuristic(task), successors, deadlineNanos, effort, searchEvaluations, workBudget);
    }

    /** @param additive the FF heuristic with h^add supporters, asked for when first needed (a solve's scratch one: made once per task) */
    PlanImprover(SearchTask task, FfHeuristic heuristic, java.util.function.Supplier<? extends FfHeuristic> additive, Successors successors,
                 long deadlineNanos, long[] effort, long searchEvaluations, long workBudget) {
        this.additiveSource = additive;
        this.searchEvaluations = searchEvaluations;
        this.workBudget = workBudget;
        this.meter = new WorkMeter(heuristic, successors);
        this.task = task;
        this.heuristic = heuristic;
        this.successors = successors;
        this.deadline = deadlineNanos;
        this.effort = effort;
    }

    /** Weights of the lazy weighted A* iterations {@link #anytime} adds, as LAMA's after its first plan. */
    static final int[] ANYTIME_WEIGHTS = {5, 3, 2, 1};
    /** Work for {@link #anytime}'s iterations, besides the budget (0: none). */
    private long anytimeWork;
    /** Work the last {@link #improve}'s iterations used. */
    private long anytimeUsed;

    /**
     * After the steps below, LAMA's later iterations get {@code work} more: lazy weighted A* with the FF
     * heuristic and the landmark count (preferred operators, four queues) with weights 5, 3, 2, 1, each
     * pruned at the best plan's length, until one finds nothing within the work. Where a greedy first
     * plan is a local optimum the neighbourhoods cannot leave (sokoban-sat11 p07: 91 steps, 89 after
     * the steps), it searches the whole space again below that length (w = 5: 84 after 29,244
     * evaluations; Fast Downward's lama-first 77). The greedy plans' length depends on which of equal
     * supporters the FF heuristic takes (sokoban's LAMA gives 83 to 117 steps over 13 operator orders):
     * this makes the result depend on them less.
     */
    PlanImprover anytime(long work) {
        anytimeWork = work;
        return this;
    }

    /** The shortest plan found, never longer than {@code plan} (a valid plan for the goal). */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan, boolean tryLazyGreedy) {
        return improve(init, goalPos, goalNeg, plan, tryLazyGreedy, false);
    }

    /**
     * @param restartAnyway the restarts run even where the smallest neighbourhood did not help: the
     *     first plan came from a search that has not been asked twice (the portfolio's), and a second
     *     search finds another route where the first one's plan is a local optimum for neighbourhoods
     */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan, boolean tryLazyGreedy, boolean restartAnyway) {
        int[] best = steps(init, goalPos, goalNeg, plan, tryLazyGreedy, restartAnyway);
        // last, action elimination that may replace an action naming an old value by its sibling
        // (woodworking-sat11 p07: 84 -> 72 steps, Fast Downward 76). Only here, on the final plan: in
        // the steps above, a plan shortened this way changed which of them ran and how far (hiking
        // p2-3-7 47 -> 52); here it can only make the plan shorter
        if (shortest) return best;
        best = PlanShortener.shorten(task, successors, init, goalPos, goalNeg, best, true);
        // after everything else, on work of its own: it can only make the plan shorter
        return anytimeWork > 0 && !timedOut ? iterations(init, goalPos, goalNeg, best) : best;
    }

    /** Work the last {@link #improve} spent in {@link #anytime}'s iterations. */
    long anytimeUsed() {
        return anytimeUsed;
    }

    private int[] iterations(int[] init, int[] goalPos, int[] goalNeg, int[] best) {
        long start = meter.now();
        try {
            return iterations(init, goalPos, goalNeg, best, start + anytimeWork);
        } finally {
            anytimeUsed = meter.now() - start;
        }
    }

    private int[] iterations(int[] init, int[] goalPos, int[] goalNeg, int[] best, long until) {
        Landmarks lms = new Landmarks(task, init, goalPos, deadline);
        for (int w : ANYTIME_WEIGHTS) {
            if (best.length <= 1 || System.nanoTime() >= deadline || meter.now() >= until) break;
            BestFirstSearch.Result r = new LazyGreedySearch(heuristic, lms, successors, deadline).weighted(w, best.length)
                    .start(init, goalPos, goalNeg).resume(meter, until, Long.MAX_VALUE);
            count(r);
            // exhausted: no plan shorter than the bound exists; otherwise the work or the time is spent
            if (r.outcome() != BestFirstSearch.Outcome.FOUND) break;
            best = shorter(best, PlanShortener.shorten(task, successors, init, goalPos, goalNeg, r.plan()));
        }
        return best;
    }

    private int[] steps(int[] init, int[] goalPos, int[] goalNeg, int[] plan, boolean tryLazyGreedy, boolean restartAnyway) {
        shortest = false;
        timedOut = false;
        improveStart = meter.now();
        workUntil = improveStart + workBudget;
        int[] best = PlanShortener.shorten(task, successors, init, goalPos, goalNeg, plan);
        if (best.length == 0) return best;
        int first = best.length;
        if (tryLazyGreedy && !expired()) {
            // LAMA's first iteration with h^add supporters (Fast Downward's FF): the better guide
            // where achievers differ in what they need (elevators p22 110 steps, 120 with level
            // supporters; tpp p25 217 against 231), rarely worse, and at half the evaluations
            // (a plan of a few steps keeps the level supporters and simple landmarks: each evaluation and
            // the landmarks cost less, and a robot's goal such as the hospital's FollowedTo, 5 steps,
            // paid a third more for nothing when it came here; with costs it now takes the cost search)
            boolean shortPlan = best.length < ADDITIVE_LAZY_STEPS;
            best = lazy(shortPlan ? heuristic : additive(), new Landmarks(task, init, goalPos, deadline, !shortPlan), init, goalPos, goalNeg, best);
        }
        // the cheap steps first: where neither the lazy search nor the smallest neighbourhood helps,
        // the first plan is likely short already and the rest of the budget is kept
        int beforeHood = best.length;
        best = neighbourhood(init, goalPos, goalNeg, best, workUntil, false);
        if (shortest || (best.length == first && !restartAnyway)) return best;
        // larger neighbourhoods only where the smallest one helped (gripper: the lazy search's plan
        // is as short as Fast Downward's, and growing the neighbourhood around it spent the whole
        // budget for nothing), for half of what is left, so that the restarts get work too
        boolean hoodHelps = best.length < beforeHood;
        if (hoodHelps) {
            long now = meter.now();
            best = neighbourhood(init, goalPos, goalNeg, best, now + Math.max(0, workUntil - now) / 2, true);
            if (shortest) return best;
        }
        // restarts on h^add supporters, greedy first (tpp p25: 209 steps where the lazy searches
        // found 217), then weighted A* (elevators p22: 92 where greedy searches find 103-120)
        boolean restartHelped = false;
        for (int[] weights : RESTARTS) {
            if (shortest || expired() || best.length <= 1) break;
            BestFirstSearch.Result r = new BestFirstSearch(task, additive(), successors, deadline).boundLength(best.length)
                    .limitWork(meter, workUntil).run(init, goalPos, goalNeg, weights[0], weights[1], true, searchEvaluations);
            count(r);
            // exhausted under the bound: no shorter plan exists for any weight; a restart that found
            // nothing within its evaluations makes the next, less greedy, one unlikely to
            if (r.outcome() != BestFirstSearch.Outcome.FOUND) break;
            best = shorter(best, postProcess(init, goalPos, goalNeg, r.plan()));
            restartHelped = true;
        }
        // what is left goes to larger neighbourhoods where they or the restarts found anything
        if (!shortest && (hoodHelps || restartHelped)) best = neighbourhood(init, goalPos, goalNeg, best, workUntil, true);
        return best;
    }

    /** Whether the last {@link #improve} was cut short by the deadline: its plan is the best found so far. */
    boolean timedOut() {
        return timedOut;
    }

    /** A restart's plan shortened, without growing neighbourhoods: they would take the budget from the next restart. */
    private int[] postProcess(int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        return neighbourhood(init, goalPos, goalNeg, PlanShortener.shorten(task, successors, init, goalPos, goalNeg, plan), workUntil, false);
    }

    private int[] neighbourhood(int[] init, int[] goalPos, int[] goalNeg, int[] plan, long until, boolean grow) {
        if (expired()) return plan;
        if (neighbourhood == null) {
            int states = Math.min(NEIGHBOURHOOD_STATES, NEIGHBOURHOOD_FACTS / (init.length + 1));
            neighbourhood = new PlanNeighbourhoodSearch(successors, Math.max(1, states));
        }
        plan = neighbourhood.limitWork(meter, until).improve(init, goalPos, goalNeg, plan, deadline, grow);
        timedOut |= neighbourhood.timedOut();
        // the neighbourhood was the whole reachable space: nothing shorter exists
        shortest |= neighbourhood.provedShortest();
        return plan;
    }

    private int[] lazy(FfHeuristic h, Landmarks lms, int[] init, int[] goalPos, int[] goalNeg, int[] best) {
        long start = meter.now();
        // three queues: the fourth (landmarks over all successors) doubles the memory on the wide tasks
        // this search runs on (logistics) and made storage p11's plan 24 steps instead of 20
        LazyGreedySearch.Run run = new LazyGreedySearch(h, lms, successors, deadline, false).start(init, goalPos, goalNeg);
        BestFirstSearch.Result r = run.resume(meter, workUntil, searchEvaluations);
        if (r.outcome() == BestFirstSearch.Outcome.LIMIT) {
            // the budget (work or evaluations) ended mid-search: where the search has come far enough
            // that its progress foretells the rest, it may go on for what that foretells (with a
            // margin), as long as the whole improvement stays within LAZY_EXTENSION times its budget
            // (logistics00 50-0: the agenda's 417 steps are cheap to find; the lazy search stops at
            // its 25,020 evaluations with the FF value 0.81 of the way down and finds 327 steps at 25,652)
            double progress = run.progress();
            if (progress >= LAZY_PROGRESS_TO_EXTEND) {
                long until = start + (long) ((meter.now() - start) / progress * LAZY_MARGIN);
                long evaluations = (long) (run.evaluated() / progress * LAZY_MARGIN);
                if (until <= improveStart + LAZY_EXTENSION * workBudget && (until > workUntil || evaluations > searchEvaluations)) {
                    workUntil = Math.max(workUntil, until);
                    // the run's counters are cumulative: only its last result is counted
                    r = run.resume(meter, workUntil, Math.max(searchEvaluations, evaluations));
                }
            }
        }
        count(r);
        if (r.outcome() != BestFirstSearch.Outcome.FOUND) return best;
        return shorter(best, PlanShortener.shorten(task, successors, init, goalPos, goalNeg, r.plan()));
    }

    /** The FF heuristic with h^add supporters, counted by the meter from the moment it is first used. */
    private FfHeuristic additive() {
        if (additive == null) {
            additive = additiveSource.get();
            meter.add(additive);
        }
        return additive;
    }

    private void count(BestFirstSearch.Result r) {
        effort[0] += r.expanded();
        effort[1] += r.evaluated();
        timedOut |= r.outcome() == BestFirstSearch.Outcome.TIMEOUT;
    }

    private boolean expired() {
        if (System.nanoTime() >= deadline) timedOut = true;
        return timedOut || meter.now() >= workUntil;
    }

    private static int[] shorter(int[] a, int[] b) {
        return b.length < a.length ? b : a;
    }
}
