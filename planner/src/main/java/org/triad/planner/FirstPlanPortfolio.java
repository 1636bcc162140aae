package org.triad.planner;

/**
 * The complete search for a first plan when the goal agenda (or a bounded single-goal A*) fails:
 * five greedy configurations take turns in slices of work ({@link WorkMeter}: about 0.5 s in the
 * first round, doubled every round):
 * <ol>
 * <li>LAMA's first iteration ({@link LazyGreedySearch} with the FF and landmark-count heuristics);</li>
 * <li>lazy greedy search with FF alone, h^add supporters ({@link AdditiveFfHeuristic}, as Fast
 *     Downward's FF);</li>
 * <li>eager greedy best-first search on FF with a boosted preferred-operator queue (restarted each
 *     turn, hence the doubling);</li>
 * <li>lazy greedy search with FF alone, level supporters;</li>
 * <li>LAMA's first iteration again with the other tie rule in FF: of a fact's achievers at its level
 *     the one met last ({@link FfHeuristic#FfHeuristic(SearchTask, boolean)}). On rubik's cube every
 *     relaxed step has one condition, so the tie rule alone picks the relaxed plan, and LAMA's plan
 *     swings with it: 137 steps after 431,318 evaluations with the first achiever, 95 after 256,657
 *     with the last (Fast Downward 93); elsewhere the last achiever is mostly worse (sokoban-sat11
 *     p07 96 against 91, depot p08 76 against 39), hence a configuration of its own, not the rule,
 *     and from the fourth round on ({@link #FIFTH_FROM_SLICE}).</li>
 * </ol>
 * The lazy searches are resumed where their last turn stopped, and one that reached a new best
 * heuristic value during its turn keeps the turn while it has used at most two thirds of the work,
 * so a search that is getting on (LAMA on woodworking, about 6 s) is barely slowed while one stuck
 * on a plateau hands over. Why not LAMA alone: where resources make states dead ends the
 * heuristics do not see (fuel, a truck's time slots), the landmark count can hold the search on a
 * plateau that FF alone leaves quickly (nomystery p07: 167 evaluations with FF alone, none within
 * 60 s with the landmark queue added; trucks p10: 21,000 evaluations eager); where level-first
 * relaxed plans mislead, h^add supporters do not (transport-sat11 p03). Slices of work units (facts
 * and operator rows touched), not evaluation counts, because evaluations differ up to tenfold in cost
 * between configurations; not time, so that the turns, and the plan, do not depend on the machine's
 * load (the deadline only ends the search). Every
 * configuration is complete (closed lists; only relaxed dead ends are pruned), so exhausting any one
 * but the h^add one proves the task unsolvable (the h^add relaxation reads preconditions and adds only;
 * where the task has more, such as conditional effects, its dead ends are no proof). After a plan,
 * {@link #shorterPlan} lets the other lazy searches go on for a budget and keeps the shortest plan.
 */
final class FirstPlanPortfolio {
    /** Work of each configuration in the first round (about half a second). */
    static final long FIRST_SLICE_WORK = WorkMeter.UNITS_PER_SECOND / 2;
    static final int CONFIGURATIONS = 5;
    /**
     * The fifth configuration joins in the fourth round (its first slice eight times the first): a
     * problem the other four solve within three rounds keeps their plan and their work. In the first
     * round it found pipesworld-tankage p17 a 94-step plan that no improvement shortened (the four, in
     * the fourth round, 108 steps, improved to 92), and recharging-robots p07 (35 steps, 98 s of CPU)
     * had no plan within 300 s at a load of 11; rubik's cube's four have not found a plan by then (their first plan took
     * 1,916 M work units), and the fifth finds its 95 steps at 2,108 M in all.
     */
    static final long FIFTH_FROM_SLICE = FIRST_SLICE_WORK << 3;
    /** A lazy search still improving its heuristic keeps its turn up to this share of the work (2/3). */
    static final long PROGRESS_SHARE_NUMERATOR = 2;
    static final long PROGRESS_SHARE_DENOMINATOR = 3;

    private final SearchTask task;
    private final FfHeuristic heuristic;
    private final Successors successors;
    private final long deadline;
    private final WorkMeter meter;
    private long work;
    private long continuedWork;
    /** The last {@link #run}'s lazy searches (null where a configuration never had a turn), for {@link #shorterPlan}. */
    private LazyGreedySearch.Run[] lazy;
    private Landmarks landmarks;
    private long[] counted;
    private int finder = -1;
    private boolean exhaustedAdditive;

    FirstPlanPortfolio(SearchTask task, FfHeuristic heuristic, Successors successors, long deadlineNanos) {
        this.task = task;
        this.heuristic = heuristic;
        this.successors = successors;
        this.deadline = deadlineNanos;
        this.meter = new WorkMeter(heuristic, successors);
    }

    /** Work units the last {@link #run} used. */
    long work() {
        return work;
    }

    /** Work units the last {@link #shorterPlan} used (all its heuristics' included). */
    long continuedWork() {
        return continuedWork;
    }

    /** FOUND, EXHAUSTED or TIMEOUT; {@code effort} gets the expansions and evaluations of all runs. */
    BestFirstSearch.Result run(int[] init, int[] goalPos, int[] goalNeg, long[] effort) {
        long begin = meter.now();
        try {
            return turns(init, goalPos, goalNeg, effort, begin);
        } finally {
            work = meter.now() - begin;
        }
    }

    private BestFirstSearch.Result turns(int[] init, int[] goalPos, int[] goalNeg, long[] effort, long begin) {
        landmarks = new Landmarks(task, init, goalPos, deadline);
        lazy = new LazyGreedySearch.Run[CONFIGURATIONS];
        long[] usedWork = new long[CONFIGURATIONS];
        counted = new long[2 * CONFIGURATIONS];
        long slice = FIRST_SLICE_WORK;
        int config = 0;
        exhaustedAdditive = false;
        finder = -1;
        while (true) {
            long now = meter.now();
            if (System.nanoTime() > deadline) return new BestFirstSearch.Result(BestFirstSearch.Outcome.TIMEOUT, null, null, 0, 0);
            if (config == 1 && exhaustedAdditive) {
                config = 2;
                continue;
            }
            if (config == 4 && slice < FIFTH_FROM_SLICE) {
                config = 0;
                slice = Math.min(slice * 2, Long.MAX_VALUE / 4);
                continue;
            }
            long until = now + slice;
            BestFirstSearch.Result r;
            boolean progressed = false;
            if (config == 2) {
                r = new BestFirstSearch(task, heuristic, successors, deadline).limitWork(meter, until)
                        .run(init, goalPos, goalNeg, 0, 1, true, Long.MAX_VALUE);
                effort[0] += r.expanded();
                effort[1] += r.evaluated();
            } else {
                long before = lazyRun(config, init, goalPos, goalNeg).evaluated();
                r = resume(config, until, effort);
                progressed = lazy[config].lastProgress() > before;
            }
            usedWork[config] += meter.now() - now;
            if (r.outcome() == BestFirstSearch.Outcome.EXHAUSTED && config == 1) {
                // its exhaustion only ends its turns: the searches with the level-based FF, whose
                // exhaustion the engine reports as unsolvable, decide that alone
                usedWork[config] = Long.MAX_VALUE / 4;
                exhaustedAdditive = true;
            } else if (r.outcome() != BestFirstSearch.Outcome.LIMIT) {
                if (r.outcome() == BestFirstSearch.Outcome.FOUND) finder = config;
                return r; // a plan, exhaustion, or the deadline
            }
            // a lazy search that reached a new best heuristic value keeps its turn, within its share
            long elapsed = meter.now() - begin;
            if (progressed && usedWork[config] * PROGRESS_SHARE_DENOMINATOR <= elapsed * PROGRESS_SHARE_NUMERATOR) continue;
            config = (config + 1) % CONFIGURATIONS;
            if (config == 0) slice = Math.min(slice * 2, Long.MAX_VALUE / 4);
        }
    }

    private LazyGreedySearch.Run lazyRun(int config, int[] init, int[] goalPos, int[] goalNeg) {
        if (lazy[config] == null) {
            FfHeuristic h = config == 1 ? new AdditiveFfHeuristic(task) : config == 4 ? new FfHeuristic(task, true) : heuristic;
            meter.add(h);
            lazy[config] = new LazyGreedySearch(h, config == 0 || config == 4 ? landmarks : null, successors, deadline).start(init, goalPos, goalNeg);
        }
        return lazy[config];
    }

    /** Resumes a lazy configuration until {@code until}; its counters are cumulative, so only what is new goes to {@code effort}. */
    private BestFirstSearch.Result resume(int config, long until, long[] effort) {
        BestFirstSearch.Result r = lazy[config].resume(meter, until, Long.MAX_VALUE);
        effort[0] += r.expanded() - counted[2 * config];
        effort[1] += r.evaluated() - counted[2 * config + 1];
        counted[2 * config] = r.expanded();
        counted[2 * config + 1] = r.evaluated();
        return r;
    }

    /**
     * After {@link #run} found {@code plan}: the other lazy configurations go on from where they
     * stopped, each for an equal share of {@code workBudget}, and the shortest plan of all is
     * returned ({@code plan} where none is shorter). The configurations differ in the route they
     * take, not only in how fast they find one: nomystery p07's 48 steps (FF on h^add supporters)
     * are a route no improvement shortens, while FF on level supporters, given the same work again,
     * finds 46 (Fast Downward 43). Work, not time: the plan does not depend on the load.
     */
    int[] shorterPlan(int[] init, int[] goalPos, int[] goalNeg, int[] plan, long workBudget, long[] effort) {
        continuedWork = 0;
        if (finder < 0 || workBudget <= 0) return plan;
        long start = meter.now();
        int others = 0;
        for (int c = 0; c < CONFIGURATIONS; c++) if (continues(c)) others++;
        int[] best = plan;
        for (int c = 0; c < CONFIGURATIONS && others > 0; c++) {
            if (!continues(c) || System.nanoTime() > deadline) continue;
            lazyRun(c, init, goalPos, goalNeg);
            BestFirstSearch.Result r = resume(c, meter.now() + workBudget / others, effort);
            if (r.outcome() == BestFirstSearch.Outcome.FOUND && r.plan().length < best.length) best = r.plan();
        }
        continuedWork = meter.now() - start;
        release();
        return best;
    }

    /** Lets the last run's searches (their states) go: improvement needs the memory. */
    void release() {
        lazy = null;
        finder = -1;
    }

    /**
     * The lazy configurations but the one that found the plan (the eager one restarts each turn:
     * nothing to go on from) and the fifth, whose share would shorten the others' (their continued
     * routes give nomystery its 46 steps).
     */
    private boolean continues(int config) {
        return config != finder && config != 2 && config != 4 && !(config == 1 && exhaustedAdditive);
    }
}
