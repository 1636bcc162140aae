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

    /** The cheapest plan found, at most as costly as {@code plan} (a valid plan for the goal). */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        if (t.axioms != null) return plan; // the relaxation here has no derived-predicate rules
        if (UnaryGraphSearch.applies(t, goalPos, goalNeg)) {
            int[] cheapest = dijkstra(init, goalPos[0]);
            return cheapest != null && cost(t, cheapest) < cost(t, plan) ? cheapest : plan;
        }
        int[] best = plan;
        double bestCost = cost(t, plan);
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

    /** Cheapest route in a graph-like task: Dijkstra over facts, ties broken by operator id. */
    private int[] dijkstra(int[] init, int goal) {
        double[] dist = new double[t.numFacts];
        int[] via = new int[t.numFacts];
        Arrays.fill(dist, Double.POSITIVE_INFINITY);
        Arrays.fill(via, -2);
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Double.compare(a[0], b[0]) : Double.compare(a[1], b[1]));
        for (int f : init) {
            dist[f] = 0;
            via[f] = -1;
            queue.add(new double[] { 0, f });
        }
        boolean[] done = new boolean[t.numFacts];
        while (!queue.isEmpty()) {
            double[] top = queue.poll();
            int f = (int) top[1];
            if (done[f]) continue;
            done[f] = true;
            if (f == goal) break;
            for (int o : t.preOf[f]) {
                work++;
                double d = dist[f] + t.ops[o].cost();
                for (int a : t.add[o]) {
                    if (d < dist[a]) {
                        dist[a] = d;
                        via[a] = o;
                        queue.add(new double[] { d, a });
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
