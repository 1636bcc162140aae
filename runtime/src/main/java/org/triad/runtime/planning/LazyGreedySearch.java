package org.triad.runtime.planning;

import java.util.Arrays;

/**
 * Lazy greedy best-first search with preferred operators, as in LAMA's first iteration: a
 * successor is queued under its parent's heuristic value and evaluated only when it is expanded,
 * so each expansion costs one heuristic evaluation. Successors reached by helpful actions also go
 * to a preferred queue, which is favoured (boosted) every time the best heuristic value improves.
 * Complete with a closed list; exhausting the queues proves the task unsolvable.
 */
final class LazyGreedySearch {
    private final FfHeuristic heuristic;
    private final Successors successors;
    private final long deadline;

    private int[] entryParent = new int[1024];
    private int[] entryOp = new int[1024];
    private int entries;

    LazyGreedySearch(FfHeuristic heuristic, Successors successors, long deadlineNanos) {
        this.heuristic = heuristic;
        this.successors = successors;
        this.deadline = deadlineNanos;
    }

    private int entry(int parent, int op) {
        if (entries == entryParent.length) {
            entryParent = Arrays.copyOf(entryParent, entries * 2);
            entryOp = Arrays.copyOf(entryOp, entries * 2);
        }
        entryParent[entries] = parent;
        entryOp[entries] = op;
        return entries++;
    }

    BestFirstSearch.Result run(int[] init, int[] goalPos, int[] goalNeg) {
        StateSpace space = new StateSpace();
        NodeHeap open = new NodeHeap();
        NodeHeap pref = new NodeHeap();
        long expanded = 0;
        long evaluated = 0;
        int bestH = Integer.MAX_VALUE;
        int boost = 0;
        boolean turn = false;
        open.push(0, entry(-1, -1));
        while (!open.isEmpty() || !pref.isEmpty()) {
            if ((evaluated & 7) == 0 && System.nanoTime() > deadline) {
                return new BestFirstSearch.Result(BestFirstSearch.Outcome.TIMEOUT, null, null, expanded, evaluated);
            }
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
            int e = q.pop();
            int parent = entryParent[e];
            int op = entryOp[e];
            int[] state = parent < 0 ? init : successors.apply(space.state(parent), op);
            if (space.find(state) >= 0) continue;
            int g = parent < 0 ? 0 : space.g(parent) + 1;
            int h = heuristic.evaluate(state, goalPos);
            evaluated++;
            int node = space.add(state, parent, op, g, h);
            if (h == FfHeuristic.INFINITE) continue;
            if (Successors.satisfies(state, goalPos, goalNeg)) {
                return new BestFirstSearch.Result(BestFirstSearch.Outcome.FOUND, space.path(node), state, expanded, evaluated);
            }
            expanded++;
            if (h < bestH) {
                bestH = h;
                boost += 1000;
            }
            int nh = heuristic.helpfulCount();
            int[] helpful = new int[nh];
            for (int i = 0; i < nh; i++) helpful[i] = heuristic.helpful(i);
            Arrays.sort(helpful);
            int n = successors.applicable(state);
            long key = h;
            // preferred successors first, so that among equal keys they are expanded first
            for (int i = 0; i < n; i++) {
                int o = successors.get(i);
                if (Arrays.binarySearch(helpful, o) >= 0) {
                    int id = entry(node, o);
                    pref.push(key, id);
                    open.push(key, id);
                }
            }
            for (int i = 0; i < n; i++) {
                int o = successors.get(i);
                if (Arrays.binarySearch(helpful, o) < 0) open.push(key, entry(node, o));
            }
        }
        return new BestFirstSearch.Result(BestFirstSearch.Outcome.EXHAUSTED, null, null, expanded, evaluated);
    }
}
