package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;

/**
 * Makes a classical plan cheaper by its action costs, for {@code (:metric minimize (total-cost))}: the
 * engine's other searches minimise the number of steps, which is what a problem without a metric asks
 * for. On a graph-like task (one goal fact, every operator needing one fact: a robot's route) Dijkstra
 * over facts gives the cheapest plan outright. Otherwise weighted A* restarts as LAMA's (weights 5, 3, 2,
 * 1 on h^add with the actions' costs), then A* on h^max (admissible: when it ends within its budget, the
 * plan is optimal); each search prunes what costs as much as the best plan so far. All of it is bounded
 * in work (operators and relaxed operators touched), never in time, so the same input gets the same plan
 * under any load; the deadline only ends improvement, and {@link #timedOut()} then says the plan is the
 * best so far.
 */
final class CostSearch {
    private static final int[] WEIGHTS = { 5, 3, 2, 1 };
    /** The optimal A* may use 1/this of the work budget before the restarts take over. */
    private static final long OPTIMAL_SHARE = 2;

    private final SearchTask t;
    private final RelaxedOps r;
    private final Successors succ;
    private final long deadline;
    private final long workLimit;
    private long work;
    private boolean timedOut;
    /** Per relaxed operator: unmet preconditions and accumulated cost during one evaluation. */
    private final int[] unmet;
    private final double[] opAcc;
    private final double[] factCost;
    private final int[] complementOf;
    /** Each operator's cost in {@link LmCut}'s integer units (sums are exact). */
    private final long[] scaledCost;
    private boolean proven;

    CostSearch(SearchTask t, Successors succ, long deadline, long workBudget) {
        this.t = t;
        this.r = t.relaxed;
        this.succ = succ;
        this.deadline = deadline;
        this.workLimit = workBudget;
        unmet = new int[r.count];
        opAcc = new double[r.count];
        factCost = new double[r.size];
        complementOf = new int[t.numFacts];
        Arrays.fill(complementOf, -1);
        for (int k = 0; k < r.negFacts.length; k++) complementOf[r.negFacts[k]] = r.numFacts + k;
        scaledCost = new long[t.ops.length];
        for (int o = 0; o < t.ops.length; o++) scaledCost[o] = LmCut.scaled(t.ops[o].cost());
    }

    /** Whether the plan {@link #improve} returned is proven the cheapest (and the shortest of the cheapest). */
    boolean proven() {
        return proven;
    }

    /** Whether the task's actions have different costs (else the shortest plan is the cheapest). */
    static boolean hasVaryingCosts(SearchTask t) {
        for (GroundOp o : t.ops) if (o.cost() != t.ops[0].cost()) return true;
        return false;
    }

    static double cost(SearchTask t, int[] plan) {
        double c = 0;
        for (int o : plan) c += t.ops[o].cost();
        return c;
    }

    /** Whether the deadline ended improvement before its work budget did. */
    boolean timedOut() {
        return timedOut;
    }

    long work() {
        return work;
    }

    /**
     * The cheapest plan and, of the cheapest, one of fewest steps, when A* under LM-cut proves it within
     * the work budget; null otherwise (also when there is no plan: the engine's other searches say why).
     * A robot's goals end here, before any search for the shortest plan.
     */
    int[] cheapest(int[] init, int[] goalPos, int[] goalNeg) {
        if (t.axioms != null) return null;
        Optimal o = optimal(init, goalPos, goalNeg, null, work + workLimit);
        proven = o.plan != null;
        return o.plan;
    }

    /** States A* expanded (for the engine's statistics). */
    long expanded() {
        return expanded;
    }

    private long expanded;

    /** The cheapest plan found, at most as costly as {@code plan} (a valid plan for the goal). */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        if (t.axioms != null) return plan; // the relaxation here has no derived-predicate rules
        if (UnaryGraphSearch.applies(t, goalPos, goalNeg)) {
            int[] cheapest = dijkstra(init, goalPos[0]);
            proven = cheapest != null;
            return cheapest != null && better(cheapest, plan) ? cheapest : plan;
        }
        int[] best = plan;
        double bestCost = cost(t, plan);
        // A* on LM-cut first, on a share of the budget: where it ends (a robot's goals), its plan is the
        // cheapest and, among the cheapest, the shortest; the restarts below only get what it leaves
        Optimal exact = optimal(init, goalPos, goalNeg, plan, work + workLimit / OPTIMAL_SHARE);
        if (exact.plan != null) {
            best = exact.plan;
            bestCost = cost(t, best);
        }
        if (exact.proven || timedOut) {
            proven = exact.proven;
            return best;
        }
        for (int w : WEIGHTS) {
            int[] p = search(init, goalPos, goalNeg, w, false, bestCost);
            if (p != null && cost(t, p) < bestCost) {
                best = p;
                bestCost = cost(t, p);
            }
            if (timedOut || work >= workLimit) return best;
        }
        int[] p = search(init, goalPos, goalNeg, 1, true, bestCost);
        return p != null && cost(t, p) < bestCost ? p : best;
    }

    /**
     * Cheapest route in a graph-like task: Dijkstra over facts on (cost, steps), so that of routes of
     * equal length in metres the one of fewer moves is taken; ties broken by operator id.
     */
    private int[] dijkstra(int[] init, int goal) {
        long[] dist = new long[t.numFacts];
        int[] steps = new int[t.numFacts];
        int[] via = new int[t.numFacts];
        Arrays.fill(dist, Long.MAX_VALUE);
        Arrays.fill(via, -2);
        PriorityQueue<long[]> queue = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Long.compare(a[0], b[0])
                : a[1] != b[1] ? Long.compare(a[1], b[1]) : Long.compare(a[2], b[2]));
        for (int f : init) {
            dist[f] = 0;
            via[f] = -1;
            queue.add(new long[] { 0, 0, f });
        }
        boolean[] done = new boolean[t.numFacts];
        while (!queue.isEmpty()) {
            long[] top = queue.poll();
            int f = (int) top[2];
            if (done[f]) continue;
            done[f] = true;
            if (f == goal) break;
            for (int o : t.preOf[f]) {
                work++;
                long d = dist[f] + scaledCost[o];
                int k = steps[f] + 1;
                for (int a : t.add[o]) {
                    if (d < dist[a] || d == dist[a] && k < steps[a]) {
                        dist[a] = d;
                        steps[a] = k;
                        via[a] = o;
                        queue.add(new long[] { d, k, a });
                    }
                }
            }
        }
        if (via[goal] == -2) return null;
        List<Integer> ops = new ArrayList<>();
        for (int f = goal; via[f] >= 0; f = t.pre[via[f]][0]) ops.add(via[f]);
        int[] plan = new int[ops.size()];
        for (int i = 0; i < plan.length; i++) plan[i] = ops.get(plan.length - 1 - i);
        return plan;
    }

    /** Whether plan {@code a} is cheaper than {@code b} or as cheap (to the micrometre) in fewer steps. */
    private boolean better(int[] a, int[] b) {
        long ca = scaledCost(a);
        long cb = scaledCost(b);
        return ca < cb || ca == cb && a.length < b.length;
    }

    private long scaledCost(int[] plan) {
        long c = 0;
        for (int o : plan) c += scaledCost[o];
        return c;
    }

    /** The outcome of {@link #optimal}: a plan (null if none better than the given one) and whether it is proven best. */
    private record Optimal(int[] plan, boolean proven) { }

    /**
     * A* on (cost, steps) under LM-cut: the cheapest plan, and among the cheapest the one of fewest steps
     * (the bound is admissible on the cost and 0 on the steps, so ordering by cost plus bound, then by
     * steps so far, is A* on the pair compared lexicographically); states reached again more cheaply are
     * reopened (LM-cut is admissible, not consistent). Prunes what cannot beat {@code incumbent}; stops
     * at {@code workEnd} (this search's {@link #work} count) unproven. Without an incumbent (null), an
     * exhausted search proves that there is no plan.
     */
    private Optimal optimal(int[] init, int[] goalPos, int[] goalNeg, int[] incumbent, long workEnd) {
        int[] goals = relaxedGoals(goalPos, goalNeg);
        boolean[] left = DominatedOps.of(t, scaledCost, goalPos, goalNeg);
        LmCut lm = lmCut(left);
        long bestCost = incumbent == null ? Long.MAX_VALUE : scaledCost(incumbent);
        int bestSteps = incumbent == null ? Integer.MAX_VALUE : incumbent.length;
        List<int[]> states = new ArrayList<>();
        long[] gCost = new long[64];
        int[] gSteps = new int[64];
        long[] fCost = new long[64];
        int[] parent = new int[64];
        int[] via = new int[64];
        Map<IntKey, Integer> seen = new HashMap<>();
        PriorityQueue<long[]> open = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Long.compare(a[0], b[0])
                : a[1] != b[1] ? Long.compare(a[1], b[1]) : Long.compare(a[2], b[2]));
        long lmWork = lm.work();
        // the initial state's bound counts against the budget like every other: on a large task one
        // LM-cut alone can outlast it, and then the search is unproven here, at the same work on every run
        long h0 = lm.value(r.initial(init), goals, lmWork + Math.max(0, workEnd - work));
        if (h0 >= LmCut.INFINITE) {
            work += lm.work() - lmWork;
            return new Optimal(null, true);
        }
        if (lm.stopped()) {
            work += lm.work() - lmWork;
            return new Optimal(null, false);
        }
        states.add(init);
        gCost[0] = 0;
        gSteps[0] = 0;
        fCost[0] = h0;
        parent[0] = -1;
        via[0] = -1;
        seen.put(new IntKey(init), 0);
        open.add(new long[] { h0, 0, 0 });
        long checks = 0;
        while (!open.isEmpty()) {
            long[] top = open.poll();
            int id = (int) top[2];
            if (top[0] != fCost[id] || top[1] != gSteps[id]) continue; // stale: reached more cheaply since
            // nothing left can beat the incumbent: it is optimal (and shortest among the optimal)
            if (top[0] > bestCost || top[0] == bestCost && top[1] >= bestSteps) break;
            int[] state = states.get(id);
            if (Successors.satisfies(state, goalPos, goalNeg)) {
                work += lm.work() - lmWork;
                return new Optimal(pathTo(parent, via, id), true);
            }
            if ((++checks & 63) == 0 && System.nanoTime() > deadline) {
                timedOut = true;
                work += lm.work() - lmWork;
                return new Optimal(null, false);
            }
            if (work + lm.work() - lmWork >= workEnd) {
                work += lm.work() - lmWork;
                return new Optimal(null, false);
            }
            expanded++;
            int count = succ.applicable(state);
            int[] ops = new int[count];
            for (int i = 0; i < count; i++) ops[i] = succ.get(i);
            work += count;
            for (int o : ops) {
                if (left != null && left[o]) continue;
                long g = gCost[id] + scaledCost[o];
                int k = gSteps[id] + 1;
                if (g > bestCost || g == bestCost && k >= bestSteps) continue;
                int[] next = succ.apply(state, o);
                IntKey key = new IntKey(next);
                Integer old = seen.get(key);
                long h;
                int n;
                if (old != null) {
                    if (old < 0 || gCost[old] < g || gCost[old] == g && gSteps[old] <= k) continue;
                    n = old;
                    h = fCost[n] - gCost[n]; // the bound depends on the state only
                } else {
                    h = lm.value(r.initial(next), goals, lmWork + Math.max(0, workEnd - work)); // a weaker bound if stopped; the loop then ends
                    if (h >= LmCut.INFINITE) {
                        seen.put(key, -1);
                        continue;
                    }
                    n = states.size();
                    states.add(next);
                    if (n == gCost.length) {
                        int cap = n * 2;
                        gCost = Arrays.copyOf(gCost, cap);
                        gSteps = Arrays.copyOf(gSteps, cap);
                        fCost = Arrays.copyOf(fCost, cap);
                        parent = Arrays.copyOf(parent, cap);
                        via = Arrays.copyOf(via, cap);
                    }
                    seen.put(key, n);
                }
                long f = g + h;
                if (f > bestCost || f == bestCost && k >= bestSteps) continue;
                gCost[n] = g;
                gSteps[n] = k;
                fCost[n] = f;
                parent[n] = id;
                via[n] = o;
                open.add(new long[] { f, k, n });
            }
        }
        work += lm.work() - lmWork;
        // exhausted under the incumbent: it is the best there is
        return new Optimal(null, true);
    }

    private static int[] pathTo(int[] parent, int[] via, int id) {
        int len = 0;
        for (int x = id; parent[x] >= 0; x = parent[x]) len++;
        int[] out = new int[len];
        for (int x = id; parent[x] >= 0; x = parent[x]) out[--len] = via[x];
        return out;
    }

    /** LM-cut over the relaxed operators, without those {@code left} leaves out (null: none). */
    private LmCut lmCut(boolean[] left) {
        long[] c = new long[r.count];
        int[][] add = r.add;
        for (int o = 0; o < r.count; o++) {
            c[o] = r.op[o] < 0 ? 0 : scaledCost[r.op[o]];
            if (left != null && r.op[o] >= 0 && left[r.op[o]]) {
                if (add == r.add) add = r.add.clone();
                add[o] = new int[0];
            }
        }
        return new LmCut(r.size, r.pre, add, c);
    }

    private record Node(int[] state, int parent, int op, double g, double f, long order) { }

    /** Weighted A* (g + w h), h^add or h^max with the actions' costs, pruning g + h^max-free bound at {@code bound}. */
    private int[] search(int[] init, int[] goalPos, int[] goalNeg, int weight, boolean max, double bound) {
        int[] goals = relaxedGoals(goalPos, goalNeg);
        List<Node> nodes = new ArrayList<>();
        Map<IntKey, Integer> seen = new HashMap<>();
        PriorityQueue<Integer> open = new PriorityQueue<>((x, y) -> {
            Node a = nodes.get(x), b = nodes.get(y);
            if (a.f != b.f) return Double.compare(a.f, b.f);
            if (a.g != b.g) return Double.compare(b.g, a.g); // deeper first among equals
            return Long.compare(a.order, b.order);
        });
        double h0 = h(init, goals, max);
        if (h0 == Double.POSITIVE_INFINITY) return null;
        nodes.add(new Node(init, -1, -1, 0, weight * h0, 0));
        seen.put(new IntKey(init), 0);
        open.add(0);
        long checks = 0;
        while (!open.isEmpty()) {
            int id = open.poll();
            Node n = nodes.get(id);
            if (seen.get(new IntKey(n.state)) != id || n.g >= bound) continue;
            if (Successors.satisfies(n.state, goalPos, goalNeg)) return planTo(nodes, id);
            if ((++checks & 63) == 0 && System.nanoTime() > deadline) {
                timedOut = true;
                return null;
            }
            if (work >= workLimit) return null;
            int count = succ.applicable(n.state);
            int[] ops = new int[count];
            for (int i = 0; i < count; i++) ops[i] = succ.get(i);
            work += count;
            for (int o : ops) {
                double g = n.g + t.ops[o].cost();
                if (g >= bound) continue;
                int[] next = succ.apply(n.state, o);
                IntKey key = new IntKey(next);
                Integer old = seen.get(key);
                if (old != null && (old < 0 || nodes.get(old).g <= g)) continue;
                double h = h(next, goals, max);
                if (h == Double.POSITIVE_INFINITY) {
                    seen.put(key, -1);
                    continue;
                }
                if (max && g + h >= bound) continue; // h^max is admissible: this cannot beat the bound
                seen.put(key, nodes.size());
                nodes.add(new Node(next, id, o, g, g + weight * h, nodes.size()));
                open.add(nodes.size() - 1);
            }
        }
        return null;
    }

    private int[] relaxedGoals(int[] goalPos, int[] goalNeg) {
        List<Integer> g = new ArrayList<>();
        for (int f : goalPos) g.add(f);
        for (int f : goalNeg) if (complementOf[f] >= 0) g.add(complementOf[f]);
        return g.stream().mapToInt(Integer::intValue).toArray();
    }

    private static int[] planTo(List<Node> nodes, int id) {
        List<Integer> ops = new ArrayList<>();
        for (int i = id; nodes.get(i).parent >= 0; i = nodes.get(i).parent) ops.add(nodes.get(i).op);
        int[] plan = new int[ops.size()];
        for (int i = 0; i < plan.length; i++) plan[i] = ops.get(plan.length - 1 - i);
        return plan;
    }

    /** h^add ({@code max} false) or h^max of the goals from a state, with the actions' costs: a Dijkstra over relaxed facts. */
    private double h(int[] state, int[] goals, boolean max) {
        Arrays.fill(factCost, Double.POSITIVE_INFINITY);
        for (int o = 0; o < r.count; o++) {
            unmet[o] = r.pre[o].length;
            opAcc[o] = 0;
        }
        work += r.count;
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Double.compare(a[0], b[0]) : Double.compare(a[1], b[1]));
        for (int f : r.initial(state)) {
            factCost[f] = 0;
            queue.add(new double[] { 0, f });
        }
        for (int o : r.noPre) fire(o, 0, queue);
        int left = goals.length;
        boolean[] isGoal = new boolean[r.size];
        for (int g : goals) isGoal[g] = true;
        boolean[] done = new boolean[r.size];
        while (!queue.isEmpty() && left > 0) {
            double[] top = queue.poll();
            int f = (int) top[1];
            if (done[f] || top[0] > factCost[f]) continue;
            done[f] = true;
            if (isGoal[f]) left--;
            for (int o : r.preOf[f]) {
                work++;
                opAcc[o] = max ? Math.max(opAcc[o], factCost[f]) : opAcc[o] + factCost[f];
                if (--unmet[o] == 0) fire(o, opAcc[o], queue);
            }
        }
        double sum = 0;
        for (int g : goals) {
            if (factCost[g] == Double.POSITIVE_INFINITY) return Double.POSITIVE_INFINITY;
            sum = max ? Math.max(sum, factCost[g]) : sum + factCost[g];
        }
        return sum;
    }

    private void fire(int o, double pre, PriorityQueue<double[]> queue) {
        double c = pre + t.ops[r.op[o]].cost();
        for (int a : r.add[o]) {
            if (c < factCost[a]) {
                factCost[a] = c;
                queue.add(new double[] { c, a });
            }
        }
    }
}
