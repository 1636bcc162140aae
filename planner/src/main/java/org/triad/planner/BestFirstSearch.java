package org.triad.planner;

import java.util.BitSet;

/**
 * Eager best-first search over a {@link SearchTask} with the FF heuristic, a closed list and
 * dead-end pruning (relaxed-unreachable goals). With {@code weightG = 1, weightH = 1} it is A*
 * (reopening nodes reached by a cheaper path); with {@code weightG = 0} it is greedy best-first
 * search, optionally with a second open list of nodes reached by helpful actions that gets
 * priority boosts whenever the heuristic improves (as in LAMA).
 */
final class BestFirstSearch {
    enum Outcome { FOUND, EXHAUSTED, LIMIT, TIMEOUT }

    record Result(Outcome outcome, int[] plan, int[] finalState, long expanded, long evaluated) { }

    private final SearchTask task;
    private final FfHeuristic heuristic;
    private final Successors successors;
    private final long deadline;
    /** Successors reached by this many actions or more are not generated: only shorter plans are sought. */
    private int lengthBound = Integer.MAX_VALUE;
    /** With {@link #limitWork}: LIMIT once the meter reaches this (a budget that does not depend on time). */
    private WorkMeter meter;
    private long workUntil = Long.MAX_VALUE;

    BestFirstSearch(SearchTask task, FfHeuristic heuristic, Successors successors, long deadlineNanos) {
        this.task = task;
        this.heuristic = heuristic;
        this.successors = successors;
        this.deadline = deadlineNanos;
    }

    /** Makes later runs look only for plans of fewer than {@code actions} actions (anytime restarts). */
    BestFirstSearch boundLength(int actions) {
        lengthBound = actions;
        return this;
    }

    /** Makes later runs stop with LIMIT once {@code meter} reaches {@code until} work units. */
    BestFirstSearch limitWork(WorkMeter meter, long until) {
        this.meter = meter;
        this.workUntil = until;
        return this;
    }

    private boolean workSpent() {
        return meter != null && meter.now() >= workUntil;
    }

    private static long key(long f, int h) {
        return (f << 24) | Math.min(h, (1 << 24) - 1);
    }

    Result run(int[] init, int[] goalPos, int[] goalNeg, int weightG, int weightH, boolean preferred, long evaluationLimit) {
        return run(init, goalPos, goalNeg, weightG, weightH, preferred, false, evaluationLimit);
    }

    /**
     * With {@code helpfulOnly}, only successors by helpful actions are generated (as in FF's
     * enforced hill-climbing): incomplete, but it keeps wide tasks cheap; callers fall back.
     */
    Result run(int[] init, int[] goalPos, int[] goalNeg, int weightG, int weightH, boolean preferred, boolean helpfulOnly,
               long evaluationLimit) {
        preferred |= helpfulOnly;
        StateSpace space = new StateSpace();
        long expanded = 0;
        long evaluated = 1;
        int h0 = heuristic.evaluate(init, goalPos);
        if (h0 == FfHeuristic.INFINITE) return new Result(Outcome.EXHAUSTED, null, null, 0, 1);
        int root = space.add(init, -1, -1, 0, h0);
        if (Successors.satisfies(init, goalPos, goalNeg)) return new Result(Outcome.FOUND, new int[0], init, 0, 1);
        boolean astar = weightG > 0;
        int[][] helpfulOf = preferred ? new int[1024][] : null;
        if (preferred) helpfulOf[root] = helpfulOps();
        NodeHeap open = new NodeHeap();
        NodeHeap pref = new NodeHeap();
        BitSet closed = new BitSet();
        open.push(key((long) weightH * h0, h0), root);
        int bestH = h0;
        int boost = 0;
        boolean turn = false;
        while (!open.isEmpty() || !pref.isEmpty()) {
            if (System.nanoTime() > deadline) return new Result(Outcome.TIMEOUT, null, null, expanded, evaluated);
            if (evaluated >= evaluationLimit || workSpent()) return new Result(Outcome.LIMIT, null, null, expanded, evaluated);
            NodeHeap q;
            if (pref.isEmpty()) {
                q = open;
            } else if (open.isEmpty() || boost > 0) {
                q = pref;
                if (boost > 0) boost--;
            } else {
                q = turn ? pref : open;
                turn = !turn;
            }
            long k = q.topKey();
            int node = q.pop();
            int g = space.g(node);
            int h = space.h(node);
            if (astar) {
                if (k != key((long) weightG * g + (long) weightH * h, h)) continue; // stale entry
                if (Successors.satisfies(space.state(node), goalPos, goalNeg)) {
                    return new Result(Outcome.FOUND, space.path(node), space.state(node), expanded, evaluated);
                }
            } else {
                if (closed.get(node)) continue;
                closed.set(node);
            }
            expanded++;
            int[] state = space.state(node);
            int[] helpful = preferred ? helpfulOf[node] : null;
            int[] ops;
            if (helpfulOnly) {
                int[] sorted = helpful.clone();
                java.util.Arrays.sort(sorted);
                int kept = 0;
                for (int o : sorted) if (successors.isApplicable(state, o)) sorted[kept++] = o;
                ops = java.util.Arrays.copyOf(sorted, kept);
            } else {
                int n = successors.applicable(state);
                ops = new int[n];
                for (int i = 0; i < n; i++) ops[i] = successors.get(i);
            }
            for (int o : ops) {
                int[] child = successors.apply(state, o);
                int existing = space.find(child);
                int cg = g + 1;
                if (cg >= lengthBound) continue;
                if (existing >= 0) {
                    if (astar && cg < space.g(existing) && space.h(existing) != FfHeuristic.INFINITE) {
                        space.reparent(existing, node, o, cg);
                        open.push(key((long) weightG * cg + (long) weightH * space.h(existing), space.h(existing)), existing);
                    }
                    continue;
                }
                if ((evaluated & 15) == 0 && System.nanoTime() > deadline) {
                    return new Result(Outcome.TIMEOUT, null, null, expanded, evaluated);
                }
                int ch = heuristic.evaluate(child, goalPos);
                evaluated++;
                int c = space.add(child, node, o, cg, ch);
                if (ch == FfHeuristic.INFINITE) continue;
                if (preferred) {
                    if (c >= helpfulOf.length) helpfulOf = java.util.Arrays.copyOf(helpfulOf, helpfulOf.length * 2);
                    helpfulOf[c] = helpfulOps();
                }
                if (!astar && Successors.satisfies(child, goalPos, goalNeg)) {
                    return new Result(Outcome.FOUND, space.path(c), child, expanded, evaluated);
                }
                long key = key((long) weightG * cg + (long) weightH * ch, ch);
                open.push(key, c);
                if (preferred && contains(helpful, o)) pref.push(key, c);
                if (ch < bestH) {
                    bestH = ch;
                    if (preferred) boost += 1000;
                }
            }
        }
        return new Result(Outcome.EXHAUSTED, null, null, expanded, evaluated);
    }

    private int[] helpfulOps() {
        int n = heuristic.helpfulCount();
        int[] out = new int[n];
        for (int i = 0; i < n; i++) out[i] = heuristic.helpful(i);
        return out;
    }

    private static boolean contains(int[] xs, int x) {
        if (xs == null) return false;
        for (int y : xs) if (y == x) return true;
        return false;
    }
}
