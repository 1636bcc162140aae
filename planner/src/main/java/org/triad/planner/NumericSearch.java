package org.triad.planner;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;

import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * Plans PDDL 2.1 numeric tasks (level 2): greedy best-first search over states of facts and fluent
 * values, guided by {@link NumericHeuristic}, ties broken by the metric so far (plan length without a
 * {@code :metric}) and then by the order actions were grounded in (so a task gets the same plan on every
 * run). An instance is applicable when its precondition holds and every value its effects compute is a
 * finite number (a division by zero or an overflow while searching makes the instance inapplicable in
 * that state, as an undefined value does in PDDL).
 * <p>
 * <b>A* first.</b> When the metric only grows (action costs) or there is none, A* on an admissible bound
 * ({@link NumericHeuristic#lowerBound}, looked up by the facts) runs first on a small budget, with
 * states pruned by {@link NumericDominance}; a plan it finds is optimal and ends planning (a robot's
 * route with a battery). When the numbers are resources only and the goal needs facts, weighted A* on
 * h_add over the facts then looks for a cheap first plan; otherwise the greedy search starts.
 * <p>
 * <b>The metric.</b> With a {@code :metric}, the first plan is then improved as LAMA and Metric-FF's
 * optimising mode do: weighted A* restarts (weights 5, 3, 2, 1) ordered by the metric so far plus a
 * cost-sensitive estimate ({@link NumericHeuristic#estimateCost}), keeping the best plan; when the metric
 * only grows along a plan (action costs, fuel used), a state as costly as the best plan is pruned.
 * Fluents that only accumulate ({@link NumericTask#accumulator}) are left out of duplicate detection
 * (the cheaper of two states that differ only in them is kept). Every budget counts heuristic
 * evaluations, never time: the same problem gets the same plan under any load; the timeout only ends
 * planning, and a plan whose improvement it cut short is flagged ({@link SolveResult#isBestSoFar()}).
 */
final class NumericSearch {
    /** States expanded before giving up, whatever the clock says. */
    static final long EXPANSION_BUDGET = 2_000_000;
    /** Improving by the metric may evaluate this many times the states the first plan needed ... */
    static final long IMPROVEMENT_FACTOR = 4;
    /** ... at least this many ... */
    static final long IMPROVEMENT_MIN_EVALUATIONS = 20_000;
    /** ... and never more than this many. */
    static final long IMPROVEMENT_MAX_EVALUATIONS = 100_000;
    private static final int[] WEIGHTS = { 5, 3, 2, 1 };
    /** The A* probe before the restarts may evaluate this many times the states the first plan needed, plus {@link #PROBE_MIN_EVALUATIONS}. */
    static final long PROBE_FACTOR = 2;
    static final long PROBE_MIN_EVALUATIONS = 2_000;
    /** States the A* search before the first greedy one may evaluate (a metric that only grows, or none). */
    static final long EXACT_FIRST_EVALUATIONS = 100_000;
    /**
     * ... and of them at most this many with facts not met before (whose bound is computed, not looked
     * up): a robot's states are many charge levels over few places, so the many are cheap.
     */
    static final long EXACT_FIRST_BOUNDS = 2_000;
    /** ... and when the goal is numbers only, whose bound is 0 (a breadth-first search then: counters' shortest plans). */
    static final long EXACT_FIRST_BLIND_EVALUATIONS = 10_000;
    /** The weight on h_add of the weighted A* that looks for a cheap first plan when the A* above gives up. */
    static final int ADDITIVE_WEIGHT = 2;
    /** Relaxed-plan evaluations the enforced hill-climbing for a goal of numbers only may spend before the greedy search takes over. */
    static final long HILL_CLIMB_EVALUATIONS = 50_000;
    /** Evaluations of the greedy search, when the goal has facts, before the enforced hill-climbing with every operator as its fallback is tried. */
    static final long GREEDY_BEFORE_CLIMB_EVALUATIONS = 100_000;
    /** The same for a problem without a metric, whose plan's length is improved. */
    static final long LENGTH_FACTOR = 2;
    static final long LENGTH_MIN_EVALUATIONS = 2_000;
    static final long LENGTH_MAX_EVALUATIONS = 50_000;

    private NumericSearch() { }

    static boolean isNumeric(Domain domain, Problem problem) {
        return org.triad.planner.pddl.NumericParts.isNumeric(domain) || org.triad.planner.pddl.NumericParts.isNumeric(problem.goal());
    }

    /** A state: facts and values; equal states may differ in the accumulators {@code ignored} marks. */
    private static final class Key {
        final BitSet facts;
        final double[] values;
        private final boolean[] ignored;
        private int hash;

        Key(BitSet facts, double[] values, boolean[] ignored) {
            this.facts = facts;
            this.values = values;
            this.ignored = ignored;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof Key k) || !k.facts.equals(facts)) return false;
            for (int i = 0; i < values.length; i++) {
                if (!ignored[i] && Double.compare(values[i], k.values[i]) != 0) return false;
            }
            return true;
        }

        @Override
        public int hashCode() {
            if (hash == 0) {
                int h = facts.hashCode();
                for (int i = 0; i < values.length; i++) if (!ignored[i]) h = 31 * h + Double.hashCode(values[i]);
                hash = h == 0 ? 1 : h;
            }
            return hash;
        }
    }

    /** {@code g}: the metric's growth since the start (plan length without a metric); {@code f}: the order of the open list. */
    private record Node(Key state, int parent, int op, double g, double f, int h, long order) { }

    private enum Outcome { FOUND, EXHAUSTED, LIMIT, TIMEOUT }

    /** One search's bookkeeping: its nodes and, when found, the goal node. */
    private static final class Run {
        final List<Node> nodes = new ArrayList<>();
        Outcome outcome;
        int goal = -1;
        long expanded;
        /** Steps left out because a value they compute is not a finite number, and the first of them. */
        long faults;
        int firstFault = -1;

        /** The state after {@code task}'s operator {@code o} in {@code s}, or null when it does not apply or computes no finite value (counted). */
        Key successor(NumericTask task, int o, Key s) {
            NumericTask.Op op = task.ops.get(o);
            if (!holds(op.pre(), s)) return null;
            Key next = apply(op, s, task.accumulator);
            if (next == null && faults++ == 0) firstFault = o;
            return next;
        }

        String faultNote(NumericTask task) {
            if (faults == 0) return "";
            return "; " + faults + " step" + (faults == 1 ? " was" : "s were") + " left out because a value computed is not a finite number"
                    + " (a division by zero or an overflow), the first " + task.ops.get(firstFault).label();
        }
    }

    static SolveResult solve(Domain domain, Problem problem, Duration timeout) {
        return solve(domain, problem, timeout, null);
    }

    /** @param groundings where groundings are kept for the next goal (null: ground afresh) */
    static SolveResult solve(Domain domain, Problem problem, Duration timeout, NumericGroundingCache groundings) {
        long start = System.nanoTime();
        long deadline = start + timeout.toNanos();
        NumericTask task;
        try {
            task = groundings == null ? new NumericTask(domain, problem) : groundings.task(domain, problem);
        } catch (PlanningInputException e) {
            return SolveResult.error(e.getMessage());
        } catch (org.triad.planner.pddl.PddlParseException e) {
            return SolveResult.error(e.getMessage());
        } catch (RuntimeException e) {
            return SolveResult.error("internal error while grounding: " + e);
        }
        double groundMs = (System.nanoTime() - start) / 1e6;
        long searchStart = System.nanoTime();
        task.leftOut = NumericDominatedOps.of(task);
        NumericHeuristic h = new NumericHeuristic(task);
        BitSet initFacts = new BitSet();
        task.initFacts.forEach(initFacts::set);
        Key init = new Key(initFacts, task.initValues, task.accumulator);
        int h0 = h.estimate(init.facts, init.values);
        if (h0 == NumericHeuristic.DEAD_END) {
            return SolveResult.unsolvable("the goal is unreachable even when nothing is ever deleted and every fluent can take any value its actions reach"
                    + task.undefinedNote(), stats(groundMs, searchStart, 0, 1));
        }
        long[] evaluations = { 1 };
        NumericDominance dominance = NumericDominance.of(task);
        Estimates cache = new Estimates();
        if (task.metric == null || h.metricOnlyGrows()) {
            // A* on the admissible bound (looked up by the facts, so cheap per state) on a small budget first:
            // a robot's route with a battery is solved optimally here, before any greedy search
            Run exact = search(task, h, dominance, init, h0, 1, Double.POSITIVE_INFINITY, true, false, true, EXPANSION_BUDGET,
                    evaluations[0] + (h.goalHasFacts() ? EXACT_FIRST_EVALUATIONS : EXACT_FIRST_BLIND_EVALUATIONS), deadline, evaluations, cache,
                    h.boundsComputed() + EXACT_FIRST_BOUNDS, 0);
            SolveResult.Stats st = stats(groundMs, searchStart, exact.expanded, evaluations[0]);
            if (exact.outcome == Outcome.FOUND) return SolveResult.solved(plan(task, opsTo(exact.nodes, exact.goal)), st);
            if (exact.outcome == Outcome.EXHAUSTED) {
                return SolveResult.unsolvable("search space exhausted" + task.undefinedNote() + exact.faultNote(task), st);
            }
            if (exact.outcome == Outcome.TIMEOUT) {
                String note = task.undefinedNote() + exact.faultNote(task);
                return note.isEmpty() ? SolveResult.timeout(st) : new SolveResult(SolveResult.Status.TIMEOUT, null, "time limit reached" + note, st);
            }
        }
        long expanded = 0;
        Run first = null;
        boolean byFacts = dominance.resourcesOnly && h.goalHasFacts();
        if ((task.metric == null || h.metricOnlyGrows()) && byFacts) {
            // numbers that are resources only: weighted A* on h_add over the facts (also looked up by the facts),
            // on the same small budget; a delivery, whose bound above sees only the longer of its two legs,
            // gets a cheap plan here
            Run cheap = search(task, h, dominance, init, h0, 1, Double.POSITIVE_INFINITY, true, false, false, EXPANSION_BUDGET,
                    evaluations[0] + EXACT_FIRST_EVALUATIONS, deadline, evaluations, cache, h.boundsComputed() + EXACT_FIRST_BOUNDS, ADDITIVE_WEIGHT);
            expanded += cheap.expanded;
            if (cheap.outcome == Outcome.FOUND) first = cheap;
        }
        if (first == null && !h.goalHasFacts()) {
            // a goal of numbers only: the layer estimate stays flat while one unit at a time is added, and the greedy
            // search gets lost on its plateaus (IPC pathwaysmetric p2); Metric-FF's enforced hill-climbing on its
            // relaxed plan with helpful actions goes through them
            Run climb = hillClimb(task, new NumericRelaxedPlan(task, h), init, evaluations[0] + HILL_CLIMB_EVALUATIONS, deadline, evaluations, false);
            expanded += climb.expanded;
            if (climb.outcome == Outcome.FOUND) first = climb;
        }
        if (first == null && h.goalHasFacts()) {
            // the greedy search below on a budget first; where it runs out, the enforced hill-climbing with Metric-FF's
            // fallback to every operator: IPC 2002 settlers p1, whose goal mixes facts with a number fed by long chains
            // of resources, is solved by it (the greedy search finds nothing in 400 s); where it also fails the greedy
            // search starts afresh with the work counter as before, so every plan it found before is found again
            long before = evaluations[0];
            Run greedy = search(task, h, dominance, init, h0, 0, Double.POSITIVE_INFINITY, false, false, false, EXPANSION_BUDGET,
                    before + GREEDY_BEFORE_CLIMB_EVALUATIONS, deadline, evaluations, cache, Long.MAX_VALUE, 0);
            expanded += greedy.expanded;
            if (greedy.outcome != Outcome.LIMIT) {
                first = greedy;
            } else {
                Run climb = hillClimb(task, new NumericRelaxedPlan(task, h, true), init, evaluations[0] + HILL_CLIMB_EVALUATIONS, deadline, evaluations, true);
                expanded += climb.expanded;
                if (climb.outcome == Outcome.FOUND || climb.outcome == Outcome.TIMEOUT) first = climb;
                else evaluations[0] = before;
            }
        }
        if (first == null) {
            first = search(task, h, dominance, init, h0, 0, Double.POSITIVE_INFINITY, false, false, false, EXPANSION_BUDGET, Long.MAX_VALUE, deadline, evaluations, cache,
                    Long.MAX_VALUE, 0);
            expanded += first.expanded;
        }
        if (first.outcome == Outcome.EXHAUSTED) {
            return SolveResult.unsolvable("search space exhausted" + task.undefinedNote() + first.faultNote(task), stats(groundMs, searchStart, expanded, evaluations[0]));
        }
        if (first.outcome != Outcome.FOUND) {
            SolveResult.Stats st = stats(groundMs, searchStart, expanded, evaluations[0]);
            String note = task.undefinedNote() + first.faultNote(task);
            return note.isEmpty() ? SolveResult.timeout(st) : new SolveResult(SolveResult.Status.TIMEOUT, null, "time limit reached" + note, st);
        }
        List<Integer> best = eliminateRedundant(task, init, opsTo(first.nodes, first.goal));
        boolean cutShort = false;
        {
            // without a metric the plan's length is improved, on a smaller budget (a robot's goal without
            // costs should not pay much for a few steps less)
            boolean byLength = task.metric == null;
            double bestCost = byLength ? best.size() : metricOf(task, init, best);
            long budget = byLength ? Math.min(LENGTH_MAX_EVALUATIONS, Math.max(LENGTH_MIN_EVALUATIONS, LENGTH_FACTOR * evaluations[0]))
                    : Math.min(IMPROVEMENT_MAX_EVALUATIONS, Math.max(IMPROVEMENT_MIN_EVALUATIONS, IMPROVEMENT_FACTOR * evaluations[0]));
            long firstWork = evaluations[0];
            boolean monotone = byLength || h.metricOnlyGrows();
            boolean proven = false;
            if (monotone) {
                // A* on the admissible bound first, on a small share: on a robot's route (a bound near the
                // true cost, states pruned by dominance) it proves a plan optimal in a few hundred states,
                // where the restarts below would evaluate thousands; otherwise little is lost
                long probe = evaluations[0] + Math.min(budget / WEIGHTS.length, PROBE_FACTOR * firstWork + PROBE_MIN_EVALUATIONS);
                Run r = search(task, h, dominance, init, h0, 1, bestCost - task.metricValue(init.values), true, false, true, EXPANSION_BUDGET, probe, deadline,
                        evaluations, cache, Long.MAX_VALUE, 0);
                expanded += r.expanded;
                if (r.outcome == Outcome.TIMEOUT) cutShort = true;
                if (r.outcome == Outcome.FOUND) {
                    List<Integer> plan = eliminateRedundant(task, init, opsTo(r.nodes, r.goal));
                    double cost = byLength ? plan.size() : metricOf(task, init, plan);
                    if (cost < bestCost) {
                        bestCost = cost;
                        best = plan;
                    }
                }
                proven = r.outcome == Outcome.FOUND || r.outcome == Outcome.EXHAUSTED;
            }
            // the restarts get the whole budget, the probe's work on top of it
            long limit = evaluations[0] + budget;
            for (int k = 0; k < WEIGHTS.length && !proven && !cutShort; k++) {
                int w = WEIGHTS[k];
                if (evaluations[0] >= limit) break;
                // each restart gets an equal share of what is left: a greedy one that cannot beat the bound
                // must not starve the less greedy ones that can
                long share = evaluations[0] + (limit - evaluations[0]) / (WEIGHTS.length - k);
                // weight 1 is A* on the cost estimate (not admissible, but it finds what the bound's A* probe could not afford);
                // with numbers that are resources only, the weighted ones are ordered by h_add over the facts, looked up
                // rather than computed (weight 1 keeps the cost estimate: on IPC delivery p2 it finds 36 where h_add gets 42)
                Run r = search(task, h, dominance, init, h0, w, monotone ? bestCost - task.metricValue(init.values) : Double.POSITIVE_INFINITY, true, !monotone,
                        false, EXPANSION_BUDGET, share, deadline, evaluations, cache, Long.MAX_VALUE, byFacts && monotone && w > 1 ? w : 0);
                expanded += r.expanded;
                if (r.outcome == Outcome.TIMEOUT) {
                    cutShort = true;
                    break;
                }
                if (r.outcome == Outcome.FOUND) {
                    List<Integer> plan = eliminateRedundant(task, init, opsTo(r.nodes, r.goal));
                    double cost = byLength ? plan.size() : metricOf(task, init, plan);
                    if (cost < bestCost) {
                        bestCost = cost;
                        best = plan;
                    }
                }
                // an exhausted search under the bound, pruned by an admissible bound, proves the best plan optimal
                if (r.outcome == Outcome.EXHAUSTED && monotone) break;
            }
        }
        SolveResult.Stats st = stats(groundMs, searchStart, expanded, evaluations[0]);
        return cutShort ? SolveResult.bestSoFar(plan(task, best), st) : SolveResult.solved(plan(task, best), st);
    }

    /**
     * Enforced hill-climbing (Hoffmann's FF and Metric-FF): from the current state, breadth-first over the
     * successors by helpful actions of the {@link NumericRelaxedPlan} until a state with a shorter relaxed
     * plan, which becomes the current one; operators in ascending order, so the plan is the same on every
     * run. With {@code full}, a breadth-first search that finds no better state is repeated over every
     * operator (Metric-FF's "pruning stopped"). Gives up ({@link Outcome#LIMIT}) when that finds none either
     * or the budget ends; the caller then searches as before.
     */
    private static Run hillClimb(NumericTask task, NumericRelaxedPlan rp, Key init, long maxEvaluations, long deadline, long[] evaluations, boolean full) {
        Run run = new Run();
        OpIndex all = full ? OpIndex.of(task) : null;
        List<Node> nodes = run.nodes;
        List<int[]> helpful = new ArrayList<>();
        int hCur = rp.evaluate(init.facts, init.values);
        evaluations[0]++;
        run.outcome = Outcome.LIMIT;
        if (hCur == NumericHeuristic.DEAD_END) return run;
        nodes.add(new Node(init, -1, -1, 0, hCur, hCur, 0));
        helpful.add(rp.helpful());
        int current = 0;
        while (true) {
            if (holds(task.goal, nodes.get(current).state)) {
                run.outcome = Outcome.FOUND;
                run.goal = current;
                return run;
            }
            int better = breadthFirst(task, rp, run, helpful, current, helpful::get, maxEvaluations, deadline, evaluations);
            if (better == STOPPED) return run;
            if (better < 0 && full) {
                // Metric-FF's "pruning stopped": the same breadth-first search over every operator
                better = breadthFirst(task, rp, run, helpful, current, id -> all.candidates(run.nodes.get(id).state.facts), maxEvaluations, deadline,
                        evaluations);
                if (better == STOPPED) return run;
            }
            if (better < 0) return run; // a dead end for the helpful actions: the caller's search takes over
            current = better;
        }
    }

    /** {@link #breadthFirst}'s answer when the run ended (its outcome says why: the deadline, or the evaluations' budget). */
    private static final int STOPPED = -2;

    /**
     * One step of the enforced hill-climbing: breadth-first from node {@code current} over the operators
     * {@code operators} gives each node, until a state with a shorter relaxed plan than the current one's, or
     * a goal state; returns its node, -1 when there is none, or {@link #STOPPED}.
     */
    private static int breadthFirst(NumericTask task, NumericRelaxedPlan rp, Run run, List<int[]> helpful, int current,
                                    java.util.function.IntFunction<int[]> operators, long maxEvaluations, long deadline, long[] evaluations) {
        List<Node> nodes = run.nodes;
        int hCur = nodes.get(current).h();
        java.util.ArrayDeque<Integer> queue = new java.util.ArrayDeque<>();
        java.util.Set<Key> seen = new java.util.HashSet<>();
        queue.add(current);
        seen.add(nodes.get(current).state);
        while (!queue.isEmpty()) {
            int id = queue.poll();
            Node n = nodes.get(id);
            if (System.nanoTime() > deadline) {
                run.outcome = Outcome.TIMEOUT;
                return STOPPED;
            }
            run.expanded++;
            for (int o : operators.apply(id)) {
                Key next = run.successor(task, o, n.state);
                if (next == null) continue;
                if (!seen.add(next)) continue;
                if (evaluations[0] >= maxEvaluations) return STOPPED;
                int hv = rp.evaluate(next.facts, next.values);
                evaluations[0]++;
                if (hv == NumericHeuristic.DEAD_END) continue;
                nodes.add(new Node(next, id, o, n.g + 1, hv, hv, nodes.size()));
                helpful.add(rp.helpful());
                if (hv < hCur || holds(task.goal, next)) return nodes.size() - 1;
                queue.add(nodes.size() - 1);
            }
        }
        return -1;
    }

    /**
     * Best-first search: greedy on the layer estimate (ties: g, then order) when {@code weight} is 0,
     * else weighted A* on g + weight * the cost estimate, reopening a state reached more cheaply and
     * pruning what cannot beat {@code bound}. With {@code allGoals} (a metric that some step makes
     * smaller, such as a battery to keep high) the estimate is the layer one and the search goes on past
     * goal states until its budget ends, returning the best goal state it met.
     */
    private static Run search(NumericTask task, NumericHeuristic h, NumericDominance dominance, Key init, int h0, int weight, double bound, boolean reopen, boolean allGoals,
                              boolean exact, long maxExpansions, long maxEvaluations, long deadline, long[] evaluations, Estimates cache,
                              long maxBounds, int additive) {
        // with a bound on a metric that only grows, a state whose cost plus an admissible estimate of the
        // rest reaches the bound cannot lead to a better plan; slack absorbs rounding in sums of costs
        boolean prune = bound != Double.POSITIVE_INFINITY && !allGoals;
        boolean unit = task.metric == null;
        double limit = bound - 1e-9 * Math.max(1, Math.abs(bound));
        OpIndex successors = OpIndex.of(task);
        // states with the same facts and other values, by their rest: one with more charge (less load) and
        // a metric no larger makes the other unnecessary (NumericDominance)
        Map<Key, List<Integer>> frontier = dominance.any ? new HashMap<>() : null;
        Run run = new Run();
        List<Node> nodes = run.nodes;
        Map<Key, Integer> seen = new HashMap<>();
        PriorityQueue<Integer> open = new PriorityQueue<>((x, y) -> {
            Node a = nodes.get(x), b = nodes.get(y);
            if (a.f != b.f) return Double.compare(a.f, b.f);
            if (a.h != b.h) return Integer.compare(a.h, b.h);
            if (a.g != b.g) return Double.compare(a.g, b.g);
            return Long.compare(a.order, b.order);
        });
        double base = task.metricValue(init.values);
        double f0 = additive > 0 ? additive * h.additive(init.facts, unit) : weight == 0 ? h0 : exact ? h.lowerBound(init.facts, init.values, unit) : weight * (allGoals ? h0 : h.estimateCost(init.facts, init.values));
        nodes.add(new Node(init, -1, -1, 0, f0, h0, 0));
        seen.put(init, 0);
        if (frontier != null) frontier.computeIfAbsent(new Key(init.facts, init.values, dominance.outsideRest), k -> new ArrayList<>()).add(0);
        open.add(0);
        while (!open.isEmpty()) {
            int id = open.poll();
            Node n = nodes.get(id);
            if (seen.get(n.state) != id) continue; // reached again more cheaply since
            if (n.g >= bound) continue;
            if (holds(task.goal, n.state)) {
                if (!allGoals) {
                    run.outcome = Outcome.FOUND;
                    run.goal = id;
                    return run;
                }
                // a metric that can fall: a later goal state may be better, so the search goes on
                if (run.goal < 0 || n.g < nodes.get(run.goal).g) run.goal = id;
            }
            if (System.nanoTime() > deadline) {
                run.outcome = Outcome.TIMEOUT;
                return run;
            }
            if (++run.expanded > maxExpansions || evaluations[0] >= maxEvaluations || h.boundsComputed() >= maxBounds) {
                run.outcome = run.goal >= 0 ? Outcome.FOUND : Outcome.LIMIT;
                return run;
            }
            for (int o : successors.candidates(n.state.facts)) {
                Key next = run.successor(task, o, n.state);
                if (next == null) continue;
                double g = task.metric == null ? n.g + 1 : task.metricValue(next.values) - base;
                Integer old = seen.get(next);
                if (old != null && (old < 0 || !reopen || nodes.get(old).g <= g)) continue;
                if (g >= bound) continue;
                List<Integer> rivals = null;
                if (frontier != null) {
                    rivals = frontier.computeIfAbsent(new Key(next.facts, next.values, dominance.outsideRest), k -> new ArrayList<>());
                    if (dominated(rivals, nodes, seen, dominance, next, g)) continue;
                }
                double lb = prune || exact ? h.lowerBound(next.facts, next.values, unit) : 0;
                if (prune && g + lb >= limit) continue;
                if (lb == Double.POSITIVE_INFINITY) {
                    seen.put(next, -1); // the goal's facts are out of reach even without deletes
                    continue;
                }
                // the exact search orders by g + the bound alone (the bound depends on the facts only, so it is
                // mostly looked up); the others evaluate the relaxed graph, once per state over all restarts
                double ha = additive > 0 ? h.additive(next.facts, unit) : 0;
                if (ha == Double.POSITIVE_INFINITY) {
                    seen.put(next, -1);
                    continue;
                }
                boolean costly = additive == 0 && !exact && weight > 0 && !allGoals;
                int hv = additive > 0 ? (int) Math.min(ha, Integer.MAX_VALUE - 1) : exact ? (int) Math.min(lb, Integer.MAX_VALUE - 1)
                        : costly ? cache.both(h, next) : cache.estimate(h, next);
                evaluations[0]++;
                if (hv == NumericHeuristic.DEAD_END) {
                    seen.put(next, -1);
                    continue;
                }
                double fv = additive > 0 ? g + additive * ha : weight == 0 ? hv : exact ? g + lb : g + weight * (allGoals ? hv : cache.estimateCost(h, next));
                seen.put(next, nodes.size());
                if (rivals != null) admit(rivals, nodes, dominance, next, g, nodes.size());
                nodes.add(new Node(next, id, o, g, fv, hv, nodes.size()));
                open.add(nodes.size() - 1);
            }
        }
        run.outcome = run.goal >= 0 ? Outcome.FOUND : Outcome.EXHAUSTED;
        return run;
    }

    /**
     * The relaxed graph's estimates of the states met so far: the restarts meet the same states again,
     * and a state's estimates do not depend on the accumulators its key leaves out (no condition reads
     * them). Bounded: past {@link #CACHED} states nothing more is kept.
     */
    private static final class Estimates {
        private static final int CACHED = 1_000_000;
        private final Map<Key, Integer> layers = new HashMap<>();
        private final Map<Key, Double> costs = new HashMap<>();

        int estimate(NumericHeuristic h, Key s) {
            Integer v = layers.get(s);
            if (v != null) return v;
            int e = h.estimate(s.facts, s.values);
            if (layers.size() < CACHED) layers.put(s, e);
            return e;
        }

        /**
         * {@link #estimate}, for a search that wants {@link #estimateCost} too: both from one graph when
         * the cost is not known yet (the weighted restarts meet states the greedy search did not).
         */
        int both(NumericHeuristic h, Key s) {
            Integer v = layers.get(s);
            if (v != null) return v;
            if (costs.containsKey(s)) return estimate(h, s);
            double c = h.estimateCost(s.facts, s.values, layer);
            if (costs.size() < CACHED) costs.put(s, c);
            if (layer[0] < 0) return estimate(h, s); // a goal out of the cost graph's reach: the layer estimate decides
            if (layers.size() < CACHED) layers.put(s, layer[0]);
            return layer[0];
        }

        private final int[] layer = new int[1];

        double estimateCost(NumericHeuristic h, Key s) {
            Double v = costs.get(s);
            if (v != null) return v;
            double e = h.estimateCost(s.facts, s.values);
            if (costs.size() < CACHED) costs.put(s, e);
            return e;
        }
    }

    /** Whether a live state of the same rest has at least as good resources at no greater metric. */
    private static boolean dominated(List<Integer> rivals, List<Node> nodes, Map<Key, Integer> seen, NumericDominance dominance, Key next, double g) {
        for (int r : rivals) {
            Node m = nodes.get(r);
            if (m.g <= g && dominance.covers(m.state.values, next.values) && !m.state.equals(next)) return true;
        }
        return false;
    }

    /** Adds a state to its rest's rivals, dropping those it dominates (they stay in the open list, but no longer prune). */
    private static void admit(List<Integer> rivals, List<Node> nodes, NumericDominance dominance, Key next, double g, int id) {
        rivals.removeIf(r -> {
            Node m = nodes.get(r);
            return g <= m.g && dominance.covers(next.values, m.state.values);
        });
        if (rivals.size() < MAX_RIVALS) rivals.add(id);
    }

    /**
     * States kept per rest to compare against: when every fluent is a resource, all states of a task whose
     * facts never change share one rest, and comparing each with all would be quadratic. Fewer rivals
     * prune less, never wrongly.
     */
    private static final int MAX_RIVALS = 16;

    /** The metric's value at the end of {@code plan} (the plan is valid). */
    private static double metricOf(NumericTask task, Key init, List<Integer> plan) {
        Key s = init;
        for (int o : plan) s = apply(task.ops.get(o), s, task.accumulator);
        return task.metricValue(s.values);
    }

    private static SolveResult.Stats stats(double groundMs, long searchStart, long expanded, long evaluated) {
        return new SolveResult.Stats(groundMs, (System.nanoTime() - searchStart) / 1e6, expanded, evaluated);
    }

    private static List<Integer> opsTo(List<Node> nodes, int id) {
        List<Integer> ops = new ArrayList<>();
        for (int i = id; nodes.get(i).parent >= 0; i = nodes.get(i).parent) ops.add(nodes.get(i).op);
        Collections.reverse(ops);
        return ops;
    }

    private static PddlPlan plan(NumericTask task, List<Integer> ops) {
        List<PddlStep> steps = new ArrayList<>();
        for (int o : ops) steps.add(new PddlStep(task.ops.get(o).name(), task.ops.get(o).args()));
        return new PddlPlan(steps);
    }

    /**
     * Greedy action elimination (Nakhost and Müller): drop one step at a time, first to last, wherever the
     * rest still applies and reaches the goal. Bounded by the square of the plan's length in step replays.
     */
    private static List<Integer> eliminateRedundant(NumericTask task, Key init, List<Integer> plan) {
        List<Integer> current = new ArrayList<>(plan);
        double cost = task.metric == null ? 0 : metricOf(task, init, current);
        for (int i = 0; i < current.size(); ) {
            List<Integer> candidate = new ArrayList<>(current);
            candidate.remove(i);
            // a step whose removal makes the metric worse stays (a metric may reward an action)
            double c = 0;
            if (reachesGoal(task, init, candidate) && (task.metric == null || (c = metricOf(task, init, candidate)) <= cost)) {
                current = candidate;
                cost = c;
            } else {
                i++;
            }
        }
        return current;
    }

    private static boolean reachesGoal(NumericTask task, Key init, List<Integer> ops) {
        Key s = init;
        for (int o : ops) {
            NumericTask.Op op = task.ops.get(o);
            if (!holds(op.pre(), s)) return false;
            s = apply(op, s, task.accumulator);
            if (s == null) return false;
        }
        return holds(task.goal, s);
    }

    /** The state after {@code op}, or null when a value it computes is not a finite number. */
    private static Key apply(NumericTask.Op op, Key s, boolean[] accumulator) {
        BitSet facts = (BitSet) s.facts.clone();
        double[] values = s.values.clone();
        List<NumericTask.Effects> active = new ArrayList<>();
        for (NumericTask.Effects e : op.effects()) if (holds(e.when(), s)) active.add(e);
        for (NumericTask.Effects e : active) for (int f : e.dels()) facts.clear(f);
        for (NumericTask.Effects e : active) for (int f : e.adds()) facts.set(f);
        for (NumericTask.Effects e : active) {
            for (NumericTask.NumEffect n : e.numeric()) {
                double amount = value(n.value(), s.values);
                double current = s.values[n.fluent()];
                String kind = n.kind();
                // by its first characters (assign, increase, decrease, scale-up, scale-down): a string
                // switch here hashed the kind for every effect of every successor
                double v = switch (kind.charAt(0)) {
                    case 'a' -> amount;
                    case 'i' -> current + amount;
                    case 'd' -> current - amount;
                    default -> kind.charAt(6) == 'u' ? current * amount : amount == 0 ? Double.NaN : current / amount;
                };
                if (!Double.isFinite(v)) return null;
                values[n.fluent()] = v == 0 ? 0 : v; // -0.0 and 0.0 are one state
            }
        }
        return new Key(facts, values, accumulator);
    }

    static boolean holds(NumericTask.Cond c, Key s) {
        if (c instanceof NumericTask.Fact f) return s.facts.get(f.id()) == f.positive();
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!holds(p, s)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (holds(p, s)) return true;
            return false;
        }
        if (c instanceof NumericTask.Const k) return k.value();
        NumericTask.Cmp m = (NumericTask.Cmp) c;
        return NumericTask.holds(m.op(), value(m.left(), s.values), value(m.right(), s.values));
    }

    /** NaN for an undefined fluent or a division by zero: every comparison with it is false. */
    private static double value(NumericTask.Expr e, double[] values) {
        return NumericTask.value(e, values);
    }

    /**
     * The operators worth trying in a state: each indexed under one positive fact of its precondition
     * (a move under the robot's place), the others always; in operator order, so successors come in the
     * same order as when every operator is tried.
     */
    private static final class OpIndex {
        private final int[][] byFact;
        private final int[] always;
        private OpIndex(int[][] byFact, int[] always) {
            this.byFact = byFact;
            this.always = always;
        }

        static OpIndex of(NumericTask task) {
            int nf = task.factNames.size();
            int[] count = new int[nf];
            int[] anchor = new int[task.ops.size()];
            List<Integer> free = new ArrayList<>();
            for (int o = 0; o < anchor.length; o++) {
                if (task.leftOut != null && task.leftOut[o]) {
                    anchor[o] = -2; // never a successor
                    continue;
                }
                anchor[o] = anchorOf(task.ops.get(o).pre());
                if (anchor[o] < 0) free.add(o);
                else count[anchor[o]]++;
            }
            int[][] byFact = new int[nf][];
            for (int f = 0; f < nf; f++) byFact[f] = new int[count[f]];
            int[] fill = new int[nf];
            for (int o = 0; o < anchor.length; o++) if (anchor[o] >= 0) byFact[anchor[o]][fill[anchor[o]]++] = o;
            return new OpIndex(byFact, free.stream().mapToInt(Integer::intValue).toArray());
        }

        /** The first positive fact of a precondition's top-level conjunction, -1 if it has none. */
        private static int anchorOf(NumericTask.Cond pre) {
            if (pre instanceof NumericTask.Fact f && f.positive()) return f.id();
            if (pre instanceof NumericTask.All a) {
                for (NumericTask.Cond c : a.parts()) if (c instanceof NumericTask.Fact f && f.positive()) return f.id();
            }
            return -1;
        }

        /** The candidates in ascending order (a fresh array: the search's loop may call this again before it ends). */
        int[] candidates(BitSet facts) {
            int n = always.length;
            for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) if (f < byFact.length) n += byFact[f].length;
            int[] out = new int[n];
            System.arraycopy(always, 0, out, 0, always.length);
            int k = always.length;
            for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) {
                if (f >= byFact.length) continue;
                System.arraycopy(byFact[f], 0, out, k, byFact[f].length);
                k += byFact[f].length;
            }
            Arrays.sort(out);
            return out;
        }
    }
}
