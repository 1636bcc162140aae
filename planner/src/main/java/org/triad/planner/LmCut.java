package org.triad.planner;

import java.util.Arrays;

/**
 * The LM-cut heuristic (Helmert and Domshlak 2009) over delete-relaxed operators with costs: an
 * admissible lower bound on the cost of reaching the goal facts, at least h^max and usually far
 * closer to the true cost. Each round computes h^max, takes the justification graph (each operator
 * hangs on its costliest precondition), cuts it between what the state reaches for free and the goal
 * zone (the facts that reach the goal through zero-cost operators), adds the cheapest cut operator's
 * cost to the bound and lowers every cut operator's cost by it, until the goal costs nothing. The cut
 * operators of one round form a disjunctive action landmark, and the cost partitioning makes the sum
 * over rounds admissible: on a delivery it counts the way to the item and the way on, where h^max sees
 * only the longer.
 * <p>
 * Costs are integers (callers scale metres to micrometres, {@link #scaled}), so sums are exact: plans of
 * equal length in metres compare equal, whichever corridors they take. Not thread-safe (scratch arrays).
 */
final class LmCut {
    static final long INFINITE = Long.MAX_VALUE / 4;
    /** Cost units per unit of an action's cost: micrometres for a cost in metres. */
    static final double SCALE = 1e6;

    private final int numFacts;
    private final int goalFact;
    private final int initFact;
    private final int count;
    private final int[][] pre;
    private final int[][] add;
    private final int[][] preOf;
    private final int[][] addOf;
    private final long[] baseCost;

    private final long[] cost;
    private final long[] hmax;
    private final int[] unmet;
    private final int[] pcf;
    private final long[] supCost;
    private final boolean[] zone;
    private final boolean[] reached;
    private final boolean[] inCut;
    private final int[] stack;
    private final int[] cutOps;
    private final NodeHeap heap = new NodeHeap();
    private long work;

    /**
     * @param numFacts facts are {@code 0 .. numFacts - 1}
     * @param pre each operator's fact preconditions
     * @param add each operator's added facts
     * @param cost each operator's cost, at least 0 ({@link #scaled})
     */
    LmCut(int numFacts, int[][] pre, int[][] add, long[] cost) {
        this.numFacts = numFacts;
        // one artificial fact true in every state (the precondition of operators that need none) and
        // one the artificial goal operator adds; that operator is the last, with the goal facts as precondition
        initFact = numFacts;
        goalFact = numFacts + 1;
        count = pre.length + 1;
        this.pre = new int[count][];
        this.add = new int[count][];
        baseCost = new long[count];
        for (int o = 0; o < pre.length; o++) {
            if (cost[o] < 0) throw new IllegalArgumentException("negative cost " + cost[o]);
            this.pre[o] = pre[o].length == 0 ? new int[] { initFact } : pre[o];
            this.add[o] = add[o];
            baseCost[o] = cost[o];
        }
        this.add[count - 1] = new int[] { goalFact };
        this.pre[count - 1] = new int[0]; // set per call
        int size = numFacts + 2;
        int[] pc = new int[size];
        int[] ac = new int[size];
        for (int o = 0; o < pre.length; o++) {
            for (int f : this.pre[o]) pc[f]++;
            for (int f : this.add[o]) ac[f]++;
        }
        preOf = new int[size][];
        addOf = new int[size][];
        for (int f = 0; f < size; f++) {
            preOf[f] = new int[pc[f]];
            addOf[f] = new int[ac[f] + (f == goalFact ? 1 : 0)];
        }
        Arrays.fill(pc, 0);
        Arrays.fill(ac, 0);
        for (int o = 0; o < pre.length; o++) {
            for (int f : this.pre[o]) preOf[f][pc[f]++] = o;
            for (int f : this.add[o]) addOf[f][ac[f]++] = o;
        }
        addOf[goalFact][0] = count - 1;
        this.cost = new long[count];
        hmax = new long[size];
        unmet = new int[count];
        pcf = new int[count];
        supCost = new long[count];
        zone = new boolean[size];
        reached = new boolean[size];
        inCut = new boolean[count];
        stack = new int[size];
        cutOps = new int[count];
    }

    /** An action's cost in the integer units LM-cut adds: rounded to a micrometre of a metre. */
    static long scaled(double cost) {
        if (!(cost >= 0)) return 0; // a negative or undefined cost counts as free (the bound stays a lower bound)
        return Math.round(Math.min(cost, INFINITE / 1e9) * SCALE);
    }

    /** Relaxed facts touched and operators relaxed so far (a work count for budgets). */
    long work() {
        return work;
    }

    /** Whether the last {@link #value} stopped on its work limit before the goal cost nothing (its bound is then weaker). */
    boolean stopped() {
        return stopped;
    }

    private boolean stopped;

    /**
     * The bound from the facts {@code state} (each below {@code numFacts}) to {@code goals}, in scaled
     * units, or {@link #INFINITE} when the goals are out of reach even without deletes.
     */
    long value(int[] state, int[] goals) {
        return value(state, goals, Long.MAX_VALUE);
    }

    /**
     * The same, stopping after the round in which {@link #work} reaches {@code workEnd}: the cuts
     * found so far still add up to a lower bound (each round's is a landmark under the costs it left),
     * only a weaker one; {@link #stopped} then says so. A bound on work, not time, so a budget that
     * ends here ends at the same place on every run.
     */
    long value(int[] state, int[] goals, long workEnd) {
        stopped = false;
        pre[count - 1] = goals;
        System.arraycopy(baseCost, 0, cost, 0, count);
        cost[count - 1] = 0;
        long g = hmax(state, goals);
        if (g >= INFINITE) return INFINITE;
        long h = 0;
        while (g > 0) {
            if (work >= workEnd) {
                stopped = true;
                return h;
            }
            long m = cut(state);
            if (m <= 0 || m >= INFINITE) return h; // cannot happen with positive h^max; stop safely
            h += m;
            lower(goals);
            g = hmax[goalFact];
        }
        return h;
    }

    /** The same with the state as a set of facts (those below {@code numFacts}). */
    long value(java.util.BitSet state, int[] goals) {
        int[] s = new int[state.cardinality()];
        int n = 0;
        for (int f = state.nextSetBit(0); f >= 0 && f < numFacts; f = state.nextSetBit(f + 1)) s[n++] = f;
        return value(n == s.length ? s : Arrays.copyOf(s, n), goals);
    }

    /**
     * h^max under the current costs over everything the state reaches (not only up to the goal's value:
     * an operator costlier than the goal may still enter the goal zone, and a cut without it would not
     * be a landmark); records each reached operator's costliest precondition in {@link #pcf} and its
     * value in {@link #supCost}.
     */
    private long hmax(int[] state, int[] goals) {
        Arrays.fill(hmax, INFINITE);
        for (int o = 0; o < count; o++) {
            unmet[o] = pre[o].length;
            pcf[o] = -1;
            supCost[o] = INFINITE;
        }
        // the goal operator's precondition is counted with multiplicity; goals appear once each
        for (int f : state) push(f, 0);
        push(initFact, 0);
        if (goals.length == 0) {
            pcf[count - 1] = initFact;
            supCost[count - 1] = 0;
            return 0;
        }
        boolean[] settled = reached; // reused as the settled marks here, cleared before cut()
        Arrays.fill(settled, false);
        while (!heap.isEmpty()) {
            long key = heap.topKey();
            int f = heap.pop();
            if (settled[f] || key > hmax[f]) continue;
            settled[f] = true;
            work++;
            for (int o : preOf[f]) fire(o, f, key);
            for (int g : goals) if (g == f) fire(count - 1, f, key);
        }
        return hmax[goalFact];
    }

    private void fire(int o, int f, long key) {
        work++;
        if (--unmet[o] != 0) return;
        // settled in order of cost: the fact completing the precondition is a costliest one
        pcf[o] = f;
        supCost[o] = key;
        long c = key + cost[o];
        for (int a : add[o]) push(a, c);
    }

    /**
     * h^max after a cut, incrementally (as Fast Downward's LM-cut does): only the cut operators got
     * cheaper, so values only fall; they fall from those operators' effects on, and an operator is
     * looked at again only when its costliest precondition fell.
     */
    private void lower(int[] goals) {
        for (int i = 0; i < lastCuts; i++) {
            int o = cutOps[i];
            long c = supCost[o] + cost[o];
            for (int a : add[o]) push(a, c);
        }
        while (!heap.isEmpty()) {
            long key = heap.topKey();
            int f = heap.pop();
            if (key > hmax[f]) continue;
            work++;
            for (int o : preOf[f]) relower(o, f, key);
            for (int g : goals) if (g == f) relower(count - 1, f, key);
        }
    }

    private void relower(int o, int f, long key) {
        work++;
        if (pcf[o] != f || supCost[o] <= key) return;
        long best = -1;
        int arg = -1;
        for (int p : pre[o]) {
            if (hmax[p] > best) {
                best = hmax[p];
                arg = p;
            }
        }
        pcf[o] = arg;
        if (best < supCost[o]) {
            supCost[o] = best;
            long c = best + cost[o];
            for (int a : add[o]) push(a, c);
        }
    }

    private void push(int f, long c) {
        if (c < hmax[f]) {
            hmax[f] = c;
            heap.push(c, f);
        }
    }

    /** One cut: lowers the cut operators' costs by the cheapest one's and returns it. */
    private long cut(int[] state) {
        // the goal zone: facts from which the goal is reached through zero-cost justification edges
        Arrays.fill(zone, false);
        int top = 0;
        zone[goalFact] = true;
        stack[top++] = goalFact;
        while (top > 0) {
            int a = stack[--top];
            for (int o : addOf[a]) {
                work++;
                int p = pcf[o];
                if (p < 0 || cost[o] != 0 || zone[p]) continue;
                zone[p] = true;
                stack[top++] = p;
            }
        }
        // what the state reaches without entering the zone; the operators leaving it into the zone are the cut
        Arrays.fill(reached, false);
        int cuts = 0;
        top = 0;
        for (int f : state) if (!reached[f]) { reached[f] = true; stack[top++] = f; }
        if (!reached[initFact]) { reached[initFact] = true; stack[top++] = initFact; }
        long m = INFINITE;
        while (top > 0) {
            int f = stack[--top];
            for (int o : preOf[f]) {
                work++;
                if (pcf[o] != f) continue;
                cuts = visit(o, cuts, top);
                top = stackTop;
            }
            if (pcf[count - 1] == f) {
                cuts = visit(count - 1, cuts, top);
                top = stackTop;
            }
        }
        for (int i = 0; i < cuts; i++) m = Math.min(m, cost[cutOps[i]]);
        for (int i = 0; i < cuts; i++) {
            cost[cutOps[i]] -= m;
            inCut[cutOps[i]] = false;
        }
        lastCuts = cuts;
        return m;
    }

    private int stackTop;
    /** The operators of the last cut: {@code cutOps[0 .. lastCuts - 1]}. */
    private int lastCuts;

    private int visit(int o, int cuts, int top) {
        boolean intoZone = false;
        for (int a : add[o]) if (zone[a]) { intoZone = true; break; }
        if (intoZone) {
            if (!inCut[o]) {
                inCut[o] = true;
                cutOps[cuts++] = o;
            }
        } else {
            for (int a : add[o]) if (!reached[a]) { reached[a] = true; stack[top++] = a; }
        }
        stackTop = top;
        return cuts;
    }
}
