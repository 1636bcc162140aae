package org.triad.planner;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PlanMetric;
import org.triad.planner.pddl.Problem;

/**
 * Triad's own planning engine. Grounds through {@link GroundedProblemCache} (so successive goals on
 * the same objects and static facts only pay for search), then:
 * <ol>
 * <li>a single open goal in a graph-like task (every relevant action needs one fact): breadth-first
 *     search over facts ({@link UnaryGraphSearch}), exact;</li>
 * <li>a single open goal in a task made of a token graph and a small remainder (a robot walking a
 *     map and acting at places): A* over the states after non-move actions, runs of moves replaced
 *     by shortest paths ({@link CompressedGraphSearch}), exact; if it exceeds its work bound:</li>
 * <li>a single open goal otherwise: A* with the FF heuristic, bounded in evaluations (the FF
 *     heuristic is not admissible, so shortest plans are likely, not guaranteed; on near-graph
 *     tasks such as a delivery the relaxed plan is close to exact);</li>
 * <li>several open goals: a goal agenda — greedy search on h with g tie-breaking, over helpful
 *     actions only (then over all actions if that fails), for one goal, then two, ... each stage
 *     continuing from the previous stage's end state and keeping the goals reached so far; the goals
 *     are taken nearest first (relaxed distance from where the last stage ended) and, within a budget,
 *     in the problem's order; the shorter plan wins;</li>
 * <li>if a bounded stage fails: {@link FirstPlanPortfolio}, LAMA-style lazy greedy best-first search
 *     (FF and landmark count, preferred operators), the same with FF alone and eager greedy search
 *     taking turns with doubling budgets (each complete, with a closed list; exhausting one proves
 *     the problem unsolvable), on {@link NegativeGoalCompilation}'s task when there are negative
 *     goals (so that the heuristics see them);</li>
 * </ol>
 * and finally makes the plan shorter: an exact search's plan is shortest already, an A* plan for a
 * single open goal (what RefArc plans per goal) only loses redundant actions; any other plan goes to {@link PlanImprover}
 * (action elimination, the lazy search when the agenda found the plan, plan neighbourhood graph
 * search, length-bounded weighted A* restarts) within a budget of work: twice the work to the first
 * plan (a share for grounding included), plus a little for several goals, never beyond the
 * improvement cap.
 * <p>
 * <b>Action costs and metrics:</b> a problem with {@code (:metric minimize (total-cost))} and actions of
 * different costs gets the plan above made cheaper by {@link CostSearch} (Dijkstra on a route, else
 * weighted A* restarts on costs), within a budget of work; any other metric ({@code maximize}, an
 * expression over fluents), and every numeric problem, is minimised by {@link NumericSearch}. A problem
 * without a metric (what RefArc plans per goal) takes none of these paths and gets the shortest plan.
 * <p>
 * <b>Deterministic:</b> every budget that decides which plan is returned counts work
 * ({@link WorkMeter}: heuristic evaluations, successor generation), never time, and every choice
 * breaks ties by ids, so the same input gives the same plan on any machine and under any load. The
 * timeout only ends planning: before the first plan it is a TIMEOUT, during improvement the best plan
 * so far is returned and said to be one ({@link SolveResult#isBestSoFar()}). Grounding keeps the
 * timeout too, and refuses a task too large for the heap before instantiating it
 * ({@link GroundingLimits}).
 */
public final class TriadEngine implements PddlPlanner {
    /** Heuristic evaluations allowed to one bounded stage before falling back. */
    static final long STAGE_EVALUATIONS = 10000;
    /**
     * Heuristic weight in goal-agenda stages: later stages start where the relaxed plan ignores the
     * way back, so A* (and even weight 5) expands the whole f-plateau around the start; a dominant
     * weight makes the stage greedy on h with ties broken by g, i.e. breadth-first across plateaus,
     * which keeps stage plans short.
     */
    static final int STAGE_WEIGHT = 1000;
    /**
     * Work (graph nodes visited plus operators tried) allowed to {@link CompressedGraphSearch}
     * before A* takes over (it also bounds the states kept): about 25 times what a delivery on a 2000-node map needs (12,000).
     */
    static final long GRAPH_SEARCH_WORK = 300_000;

    /**
     * Default cap on the work spent making a first plan shorter ({@link PlanImprover}), in
     * {@link WorkMeter} units: about 10 s of one core, reached only by first plans of more than about
     * 300 steps (the time cap it replaces was 10 s of wall time, which on a loaded machine bought less).
     */
    public static final long IMPROVEMENT_CAP = 10 * WorkMeter.UNITS_PER_SECOND;
    /**
     * Work granted to improving a plan of several goals, besides the work to the first plan:
     * enough for the lazy search and a few rounds of neighbourhood search on small tasks (about
     * 20 ms), while a planner embedded in a robot stays within a small factor of the first plan.
     */
    static final long IMPROVEMENT_EXTRA_WORK = WorkMeter.UNITS_PER_SECOND / 50;

    /** Improving may take this many times the work to the first plan (grounding's share included). */
    static final long IMPROVEMENT_WORK_FACTOR = 2;
    /**
     * Grounding's share of the work to the first plan, per ground operator of the task searched: the
     * improver's budget once grew with grounding time, which is large where a task is wide.
     */
    static final long GROUNDING_WORK_PER_OP = 200;
    /**
     * Work the goal agenda may use in all (about 3 s) before the complete portfolio takes over; each
     * stage is further bounded by {@link #STAGE_EVALUATIONS}.
     */
    static final long AGENDA_WORK = 3 * WorkMeter.UNITS_PER_SECOND;
    /**
     * Each improving search (the lazy one, every restart) may evaluate this many times the states the
     * first plan needed, at least {@link #IMPROVEMENT_MIN_EVALUATIONS}: one that needs far more rarely
     * pays off, and a failed one leaves work to the next.
     */
    static final long IMPROVEMENT_EVALUATION_FACTOR = 5;
    static final long IMPROVEMENT_MIN_EVALUATIONS = 1000;
    /**
     * Work a plan of a problem with action costs and {@code (:metric minimize (total-cost))} may always
     * spend on becoming cheaper (about 0.2 s), whatever the first plan cost.
     */
    static final long COST_MIN_WORK = WorkMeter.UNITS_PER_SECOND / 5;
    /**
     * Work the cost-optimal A* ({@link CostSearch#cheapest}) may spend before the shortest plan is
     * searched for and made cheaper (about 20 ms; a hospital delivery needs about a tenth of it).
     */
    static final long COST_FIRST_WORK = WorkMeter.UNITS_PER_SECOND / 50;
    /**
     * Work granted to improving a first plan of several goals per square of its length
     * ({@link WorkMeter} units): a longer plan needs more evaluations, each on a larger task, so a
     * 60-step plan gets about 0.4 s worth more, 117 steps 1.4 s, 250 steps 6 s, within
     * {@link #IMPROVEMENT_CAP} (elevators p22 117 steps to 93, p30 252 to 209, tpp p28 to 228; Fast
     * Downward 96, 207, 238).
     */
    static final long IMPROVEMENT_WORK_PER_SQUARED_STEP = WorkMeter.UNITS_PER_SECOND / 10_000;
    /**
     * A first plan of several goals from the goal agenda may get up to this many times the
     * improvement cap from its share per squared step (plans of more than about 320 steps):
     * logistics00 50-0's 417 steps get 17 s worth, and the lazy search that finds 327 needs about 15.
     * Such plans are cheap to find and long because the agenda ships one goal at a time, so the
     * work goes where the plan is long; a plan the portfolio found still gets at most half the cap.
     */
    static final long LONG_PLAN_CAP_FACTOR = 2;
    /** Evaluations each improving search may use per step of such a plan (elevators p22 needs 45). */
    static final long IMPROVEMENT_EVALUATIONS_PER_STEP = 60;

    private final GroundedProblemCache cache;
    /** Numeric groundings, kept as {@link #cache} keeps classical ones (a robot's goals with a battery). */
    private final NumericGroundingCache numericGroundings = new NumericGroundingCache(8);
    private final long improvementCap;

    public TriadEngine() {
        this(new GroundedProblemCache(8));
    }

    public TriadEngine(GroundedProblemCache cache) {
        this(cache, IMPROVEMENT_CAP);
    }

    /**
     * @param improvementCap the most work ({@link WorkMeter} units, {@link #IMPROVEMENT_CAP} by default)
     *     spent after the first plan looking for a shorter one (it is at most twice the work to the
     *     first plan plus a little; zero keeps the first plan after removing redundant actions)
     */
    public TriadEngine(GroundedProblemCache cache, long improvementCap) {
        if (improvementCap < 0) throw new IllegalArgumentException("negative improvement cap " + improvementCap);
        this.cache = cache;
        this.improvementCap = improvementCap;
    }

    public GroundedProblemCache cache() {
        return cache;
    }

    @Override
    public String name() {
        return "triad";
    }

    @Override
    public SolveResult solve(Domain domain, Problem problem, Duration timeout) {
        if (NumericSearch.isNumeric(domain, problem)) {
            return NumericSearch.solve(domain, problem, timeout, numericGroundings); // PDDL 2.1 numeric fluents: a search of their own
        }
        PlanMetric metric;
        try {
            metric = PlanMetric.of(problem);
        } catch (PddlParseException e) {
            return SolveResult.error(e.getMessage());
        }
        if (metric != null && !metric.isTotalCost() && !isPlanLength(metric)) {
            return NumericSearch.solve(domain, problem, timeout, numericGroundings); // any other metric: the numeric search minimises it
        }
        boolean minimizeCost = metric != null && metric.isTotalCost();
        long start = System.nanoTime();
        long deadline = start + timeout.toNanos();
        GroundedProblem.Query q;
        try {
            q = GroundingLimits.withDeadline(deadline, () -> cache.get(domain, problem).query(problem));
        } catch (GroundingTimeoutException e) {
            return new SolveResult(SolveResult.Status.TIMEOUT, null, e.getMessage(), new SolveResult.Stats((System.nanoTime() - start) / 1e6, 0, 0, 0));
        } catch (PlanningInputException e) {
            return SolveResult.error(e.getMessage());
        } catch (OutOfMemoryError e) {
            // the estimates refuse what cannot fit; this is what they missed (the grounding is dropped)
            return SolveResult.error(outOfMemory("grounding"));
        } catch (RuntimeException e) {
            return SolveResult.error("internal error while grounding: " + e);
        }
        double groundMs = (System.nanoTime() - start) / 1e6;
        long searchStart = System.nanoTime();
        if (q.unsolvableReason() != null) {
            return SolveResult.unreachable(q.unsolvableReason(), q.unreachable(), new SolveResult.Stats(groundMs, 0, 0, 0));
        }
        try {
            SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
            SearchTask.Scratch scratch = task.takeScratch();
            try {
                return search(q, task, scratch, groundMs, searchStart, deadline, minimizeCost);
            } finally {
                task.returnScratch(scratch);
            }
        } catch (OutOfMemoryError e) {
            // the search's states are garbage once this returns: the caller (a robot's planner
            // component) fails this goal, not the JVM
            return SolveResult.error(outOfMemory("search"));
        }
    }

    /** {@code minimize (total-time)}: a sequential plan's number of steps, which the engine minimises anyway. */
    private static boolean isPlanLength(PlanMetric m) {
        return m.minimize() && m.expression() instanceof org.triad.planner.pddl.NumericExpr.Fluent f && f.name().equals(PlanMetric.TOTAL_TIME);
    }

    private static String outOfMemory(String phase) {
        return "out of memory in " + phase + ": the task needs more than the memory given (" + (Runtime.getRuntime().maxMemory() >> 20) + " MB)";
    }

    private SolveResult search(GroundedProblem.Query q, SearchTask task, SearchTask.Scratch scratch, double groundMs,
                              long searchStart, long deadline, boolean minimizeCost) {
        FfHeuristic h = scratch.heuristic();
        Successors succ = scratch.successors();
        BestFirstSearch search = new BestFirstSearch(task, h, succ, deadline);
        WorkMeter meter = new WorkMeter(h, succ);
        long workAtStart = meter.now();
        long portfolioWork = 0;
        long[] effort = new long[2];
        int[] plan = null;

        boolean exact = false;
        boolean fromAgenda = false;
        boolean singleGoalAstar = false;
        List<Integer> open = new ArrayList<>();
        for (int g : q.goalPos()) if (Arrays.binarySearch(q.init(), g) < 0) open.add(g);
        if (minimizeCost && improvementCap > 0 && CostSearch.hasVaryingCosts(task)) {
            // the cheapest plan outright when A* under LM-cut proves it on a small budget (a robot's goal
            // in metres): no shortest plan to find and make cheaper
            CostSearch cheapest = new CostSearch(task, succ, deadline, COST_FIRST_WORK);
            int[] p = cheapest.cheapest(q.init(), q.goalPos(), q.goalNeg());
            effort[0] += cheapest.expanded();
            if (p != null) return solved(task, p, false, stats(groundMs, searchStart, effort));
        }
        if (open.size() == 1 && UnaryGraphSearch.applies(task, q.goalPos(), q.goalNeg())) {
            plan = UnaryGraphSearch.search(task, q.init(), q.goalPos()[0]);
            exact = true;
            if (plan == null) return SolveResult.unsolvable("goal unreachable in the transition graph", stats(groundMs, searchStart, effort));
        } else if (open.size() <= 1) {
            boolean tryAstar = true;
            if (CompressedGraphSearch.applies(task, q.init(), q.goalPos(), q.goalNeg())) {
                CompressedGraphSearch.Result r = new CompressedGraphSearch(task, succ, deadline, GRAPH_SEARCH_WORK)
                        .run(q.init(), q.goalPos(), q.goalNeg());
                effort[0] += r.expanded();
                effort[1] += r.generated();
                if (r.outcome() == BestFirstSearch.Outcome.FOUND) {
                    plan = r.plan();
                    exact = true;
                }
                if (r.outcome() == BestFirstSearch.Outcome.EXHAUSTED) {
                    return SolveResult.unsolvable("search space exhausted", stats(groundMs, searchStart, effort));
                }
                tryAstar = r.outcome() == BestFirstSearch.Outcome.LIMIT;
            }
            if (tryAstar) {
                BestFirstSearch.Result r = search.run(q.init(), q.goalPos(), q.goalNeg(), 1, 1, false, STAGE_EVALUATIONS);
                effort[0] += r.expanded();
                effort[1] += r.evaluated();
                if (r.outcome() == BestFirstSearch.Outcome.FOUND) {
                    plan = r.plan();
                    // A* on one open goal: near shortest already, and this is what RefArc plans per goal,
                    // so it only loses redundant actions (improving it cost the hospital's goals 2-4x)
                    singleGoalAstar = true;
                }
                if (r.outcome() == BestFirstSearch.Outcome.EXHAUSTED) {
                    return SolveResult.unsolvable("search space exhausted", stats(groundMs, searchStart, effort));
                }
            }
        } else {
            // the agenda may use a bounded amount of work (not time: its plan must not depend on the
            // load); the complete search gets the rest of the time
            plan = agenda(q, new BestFirstSearch(task, h, succ, deadline).limitWork(meter, meter.now() + AGENDA_WORK), h, open, effort);
            fromAgenda = plan != null;
        }
        NegativeGoalCompilation compiledPlan = null;
        FirstPlanPortfolio portfolio = null;
        if (plan == null && System.nanoTime() < deadline) {
            long beforePortfolio = meter.now();
            NegativeGoalCompilation c = NegativeGoalCompilation.of(task, q.init(), q.goalPos(), q.goalNeg());
            BestFirstSearch.Result r = null;
            if (c != null) {
                FirstPlanPortfolio compiled = new FirstPlanPortfolio(c.task, new FfHeuristic(c.task), new Successors(c.task), deadline);
                r = compiled.run(c.init, c.goalPos, new int[0], effort);
                portfolioWork += compiled.work();
            }
            // the compiled plan is replayed on the task itself, which alone knows every effect and rule
            if (r != null && r.outcome() == BestFirstSearch.Outcome.FOUND && !solves(succ, q, r.plan())) r = null;
            if (r != null) compiledPlan = c;
            if (r == null) {
                portfolio = new FirstPlanPortfolio(task, h, succ, deadline);
                r = portfolio.run(q.init(), q.goalPos(), q.goalNeg(), effort);
                // its own heuristics' work besides what the meter saw of h and succ
                portfolioWork += portfolio.work() - (meter.now() - beforePortfolio);
            }
            if (r.outcome() == BestFirstSearch.Outcome.FOUND) plan = r.plan();
            if (r.outcome() == BestFirstSearch.Outcome.EXHAUSTED) {
                return SolveResult.unsolvable("search space exhausted", stats(groundMs, searchStart, effort));
            }
        }
        if (plan == null) return SolveResult.timeout(stats(groundMs, searchStart, effort));
        if (portfolio != null && improvementCap <= 0) portfolio.release();
        boolean bestSoFar = false;
        long anytimeUsed = 0;
        if (exact) {
            // a shortest plan: nothing to eliminate (and elimination is quadratic in its length:
            // a chain of 100,000 places)
        } else if (singleGoalAstar || improvementCap <= 0) {
            plan = PlanShortener.shorten(task, succ, q.init(), q.goalPos(), q.goalNeg(), plan);
        } else {
            long firstPlan = meter.now() - workAtStart + portfolioWork + GROUNDING_WORK_PER_OP * task.ops.length;
            // a single goal's A* plan is near shortest: no extra work, so small goals stay fast
            // several goals: a little more, and more the longer the plan is (a cheap first plan of
            // hundreds of steps, as the agenda finds for elevators or tpp, is where improving pays).
            // A plan the portfolio found gets twice its work and its share per squared step, at most
            // half the cap, so that improving it does not double a long search (depot); without the
            // squared share, sokoban-sat11 p07's 119 portfolio steps got 0.35 s worth and ended at
            // 101 (93 with it; Fast Downward 77)
            // negative goals count as goals too (quantum-layout's are all negative: every gate done)
            int goals = open.size();
            for (int g : q.goalNeg()) if (Arrays.binarySearch(q.init(), g) >= 0) goals++;
            long budget = improvementBudget(improvementCap, firstPlan, plan.length, goals, fromAgenda);
            // a greedy plan of the portfolio: LAMA's later iterations get as much work again as the
            // improvement (only a shorter plan replaces it, so no plan gets longer), where that is more
            // than the first plan took: a search below its length explores more than the greedy one did
            // (sokoban p07: 29,244 evaluations to 84 after 2,667 to 91), so with less it cannot end
            // (rubiks-cube p07: its first plan took 431,318, and 300,000 below 129 found nothing)
            long anytime = goals > 1 && (portfolio != null || compiledPlan != null) && budget >= firstPlan ? budget : 0;
            if (portfolio != null && goals <= 1) portfolio.release();
            if (portfolio != null && goals > 1) {
                // the portfolio's other searches go on first, for as much work as it took to the plan
                // (within the improvement's budget, which pays for it): another route, where the first
                // plan's is one no improvement shortens (nomystery p07 48 -> 46, Fast Downward 43)
                plan = portfolio.shorterPlan(q.init(), q.goalPos(), q.goalNeg(), plan, Math.min(budget / 2, portfolio.work()), effort);
                budget -= Math.min(budget, portfolio.continuedWork());
            }
            long evaluations = Math.max(Math.max(IMPROVEMENT_MIN_EVALUATIONS, IMPROVEMENT_EVALUATION_FACTOR * effort[1]),
                    goals <= 1 ? 0 : IMPROVEMENT_EVALUATIONS_PER_STEP * plan.length);
            int[] improved;
            PlanImprover improver;
            if (compiledPlan != null) {
                // improved where it was found: on the task itself the heuristics do not see negative
                // goals, so the restarts would search blind (quantum-layout p07: 35 steps, 24 this way; Fast Downward 31)
                NegativeGoalCompilation c = compiledPlan;
                improver = new PlanImprover(c.task, new FfHeuristic(c.task), () -> new AdditiveFfHeuristic(c.task), new Successors(c.task),
                        deadline, effort, evaluations, budget).anytime(anytime);
                improved = improver.improve(c.init, c.goalPos, new int[0], plan, fromAgenda, goals > 1 && !fromAgenda);
            } else {
                improver = new PlanImprover(task, h, () -> scratch.additive(task), succ, deadline, effort, evaluations, budget).anytime(anytime);
                improved = improver.improve(q.init(), q.goalPos(), q.goalNeg(), plan, fromAgenda, goals > 1 && !fromAgenda);
            }
            if (compiledPlan == null || solves(succ, q, improved)) plan = improved;
            // the cost search's budget below grows with the work so far (this meter's), not with the iterations'
            if (compiledPlan == null) anytimeUsed = improver.anytimeUsed();
            bestSoFar = improver.timedOut();
        }
        if (minimizeCost && improvementCap > 0 && CostSearch.hasVaryingCosts(task)) {
            // (:metric minimize (total-cost)): the plan above is short; make it cheap, within a budget of work
            long firstPlan = meter.now() - workAtStart + portfolioWork - anytimeUsed + GROUNDING_WORK_PER_OP * task.ops.length;
            long budget = Math.min(improvementCap, Math.max(COST_MIN_WORK, IMPROVEMENT_WORK_FACTOR * firstPlan));
            CostSearch cheaper = new CostSearch(task, succ, deadline, budget);
            plan = cheaper.improve(q.init(), q.goalPos(), q.goalNeg(), plan);
            bestSoFar |= cheaper.timedOut();
        }
        return solved(task, plan, bestSoFar, stats(groundMs, searchStart, effort));
    }

    private static SolveResult solved(SearchTask task, int[] plan, boolean bestSoFar, SolveResult.Stats stats) {
        List<PddlStep> steps = new ArrayList<>(plan.length);
        for (int o : plan) if (!task.ops[o].artificial()) steps.add(task.ops[o].toAction());
        PddlPlan result = new PddlPlan(steps);
        return bestSoFar ? SolveResult.bestSoFar(result, stats) : SolveResult.solved(result, stats);
    }

    /**
     * The work improving a first plan may use: twice the work to it, more for a plan of several goals
     * (see {@link #search}'s comment), within the cap.
     *
     * @param firstPlanWork work to the first plan, grounding's share included
     */
    static long improvementBudget(long improvementCap, long firstPlanWork, int steps, int openGoals, boolean fromAgenda) {
        long squared = openGoals <= 1 ? 0 : IMPROVEMENT_WORK_PER_SQUARED_STEP * steps * steps;
        long extra = openGoals <= 1 ? 0 : IMPROVEMENT_EXTRA_WORK + (fromAgenda ? squared : 0);
        long own = IMPROVEMENT_WORK_FACTOR * firstPlanWork + (fromAgenda ? 0 : squared);
        long cap = fromAgenda && openGoals > 1 ? LONG_PLAN_CAP_FACTOR * improvementCap : improvementCap;
        return Math.min(cap, Math.min(improvementCap / 2, own) + extra);
    }

    private static boolean solves(Successors succ, GroundedProblem.Query q, int[] plan) {
        int[] state = q.init();
        for (int o : plan) {
            if (!succ.isApplicable(state, o)) return false;
            state = succ.apply(state, o);
        }
        return Successors.satisfies(state, q.goalPos(), q.goalNeg());
    }

    /**
     * Goals achieved cumulatively, each stage continuing from where the previous one ended and keeping
     * the goals of the earlier stages. Two orders, the shorter plan wins:
     * <ul>
     * <li>nearest first: each stage adds the open goal nearest (in relaxed steps) to where the previous
     *     stage ended, which keeps a tour of many places (visitall, deliveries) from zig-zagging;</li>
     * <li>as given: the goals in the problem's order, which suits goals that must be built in order
     *     (blocks); it may spend at most twice the heuristic evaluations the first order needed, so it
     *     costs little where it does not help.</li>
     * </ul>
     */
    private int[] agenda(GroundedProblem.Query q, BestFirstSearch search, FfHeuristic h, List<Integer> open, long[] effort) {
        long before = effort[1];
        int[] nearest = agenda(q, search, h, open, effort, true, Long.MAX_VALUE);
        long used = effort[1] - before;
        int[] given = agenda(q, search, h, open, effort, false, nearest == null ? Long.MAX_VALUE : 2 * used + 100);
        if (nearest == null) return given;
        return given != null && given.length < nearest.length ? given : nearest;
    }

    private int[] agenda(GroundedProblem.Query q, BestFirstSearch search, FfHeuristic h, List<Integer> open, long[] effort,
                         boolean nearestFirst, long evaluationBudget) {
        List<Integer> remaining = new ArrayList<>(open);
        List<Integer> done = new ArrayList<>();
        for (int g : q.goalPos()) if (!open.contains(g)) done.add(g);
        int[] state = q.init();
        List<Integer> plan = new ArrayList<>();
        long spent = 0;
        while (!remaining.isEmpty()) {
            int next = nearestFirst ? h.nearest(state, remaining.stream().mapToInt(Integer::intValue).toArray()) : remaining.get(0);
            if (next < 0) return null;
            remaining.remove(Integer.valueOf(next));
            done.add(next);
            boolean last = remaining.isEmpty();
            int[] goals = Grounder.sortedUnique(done);
            int[] neg = last ? q.goalNeg() : new int[0];
            long limit = Math.min(STAGE_EVALUATIONS, evaluationBudget - spent);
            if (limit <= 0) return null;
            BestFirstSearch.Result r = search.run(state, goals, neg, 1, STAGE_WEIGHT, false, true, limit);
            spent += r.evaluated();
            if (r.outcome() != BestFirstSearch.Outcome.FOUND && r.outcome() != BestFirstSearch.Outcome.TIMEOUT) {
                limit = Math.min(STAGE_EVALUATIONS, evaluationBudget - spent);
                if (limit <= 0) return null;
                effort[0] += r.expanded();
                effort[1] += r.evaluated();
                r = search.run(state, goals, neg, 1, STAGE_WEIGHT, false, false, limit);
                spent += r.evaluated();
            }
            effort[0] += r.expanded();
            effort[1] += r.evaluated();
            if (r.outcome() != BestFirstSearch.Outcome.FOUND) return null;
            for (int o : r.plan()) plan.add(o);
            state = r.finalState();
            // nearest first: goals reached on the way are kept from now on (as given, they wait for
            // their turn: protecting them early can force detours where goals must be built in order)
            for (java.util.Iterator<Integer> it = remaining.iterator(); nearestFirst && it.hasNext(); ) {
                int g = it.next();
                if (Arrays.binarySearch(state, g) >= 0) {
                    it.remove();
                    done.add(g);
                }
            }
        }
        // the last goals may have been reached on the way, before any stage had to respect the negative goals
        if (!Successors.satisfies(state, q.goalPos(), q.goalNeg())) {
            long limit = Math.min(STAGE_EVALUATIONS, evaluationBudget - spent);
            if (limit <= 0) return null;
            BestFirstSearch.Result r = search.run(state, q.goalPos(), q.goalNeg(), 1, STAGE_WEIGHT, false, false, limit);
            effort[0] += r.expanded();
            effort[1] += r.evaluated();
            if (r.outcome() != BestFirstSearch.Outcome.FOUND) return null;
            for (int o : r.plan()) plan.add(o);
        }
        return plan.stream().mapToInt(Integer::intValue).toArray();
    }

    private static SolveResult.Stats stats(double groundMs, long searchStart, long[] effort) {
        return new SolveResult.Stats(groundMs, (System.nanoTime() - searchStart) / 1e6, effort[0], effort[1]);
    }
}
