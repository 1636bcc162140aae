package org.triad.planner;

import java.util.Arrays;

/**
 * Lazy greedy best-first search with preferred operators and two heuristics, as in LAMA's first
 * iteration: a successor is queued under its parent's values and evaluated only when expanded.
 * Four queues, as Fast Downward's lama-first has (FF and landmark count, each over all successors and
 * over preferred ones; without landmarks the two FF queues), are used round-robin, and the preferred
 * ones are boosted every time either heuristic improves. The landmark queue over all successors lets
 * the search follow landmarks where FF's preferred operators lead astray (sokoban-sat11 p07: 91 steps
 * instead of 119); it doubles the queues' memory on wide tasks (logistics00 75-0: 150 to 326 MB live
 * after 15,000 evaluations), so the plan improver, whose lazy search runs on those (the goal agenda's
 * logistics plans), leaves it out: see planner/BENCHMARK.md, sixth session. Complete with a closed
 * list; exhausting the queues proves the task unsolvable (dead ends are relaxed-unsolvable states).
 * {@link #weighted} makes it LAMA's later iterations (lazy weighted A* below a length bound).
 */
final class LazyGreedySearch {
    private final FfHeuristic heuristic;
    private final Landmarks landmarks;
    private final Successors successors;
    private final long deadline;
    private final boolean landmarkQueueOverAll;
    /** 0: greedy (keys are heuristic values); otherwise keys are g + weight * h, and a shorter path reopens a state. */
    private int weight;
    /** Paths of this many steps or more are pruned (only shorter plans are looked for). */
    private int lengthBound = Integer.MAX_VALUE;

    private int[] entryParent = new int[1024];
    private int[] entryOp = new int[1024];
    private int entries;

    /** {@code landmarks} may be null: then only the FF queues are used. */
    LazyGreedySearch(FfHeuristic heuristic, Landmarks landmarks, Successors successors, long deadlineNanos) {
        this(heuristic, landmarks, successors, deadlineNanos, true);
    }

    /** Without {@code landmarkQueueOverAll}, landmarks order only the preferred successors (three queues). */
    LazyGreedySearch(FfHeuristic heuristic, Landmarks landmarks, Successors successors, long deadlineNanos, boolean landmarkQueueOverAll) {
        this.landmarkQueueOverAll = landmarkQueueOverAll;
        this.heuristic = heuristic;
        this.landmarks = landmarks;
        this.successors = successors;
        this.deadline = deadlineNanos;
    }

    /**
     * Lazy weighted A* as in LAMA's later iterations: successors keyed by their g plus {@code weight}
     * times their parent's heuristic values, a state reached again on a shorter path reopened (its
     * values kept), and paths of {@code lengthBound} steps or more pruned, so a plan found is shorter.
     */
    LazyGreedySearch weighted(int weight, int lengthBound) {
        if (weight < 1) throw new IllegalArgumentException("weight " + weight);
        this.weight = weight;
        this.lengthBound = lengthBound;
        return this;
    }

    private int entry(int parent, int op) {
        if (entries == entryParent.length) {
            int cap = entries + (entries >> 1);
            entryParent = Arrays.copyOf(entryParent, cap);
            entryOp = Arrays.copyOf(entryOp, cap);
        }
        entryParent[entries] = parent;
        entryOp[entries] = op;
        return entries++;
    }

    BestFirstSearch.Result run(int[] init, int[] goalPos, int[] goalNeg) {
        return run(init, goalPos, goalNeg, Long.MAX_VALUE);
    }

    /** Stops with {@code LIMIT} after {@code evaluationLimit} heuristic evaluations. */
    BestFirstSearch.Result run(int[] init, int[] goalPos, int[] goalNeg, long evaluationLimit) {
        return start(init, goalPos, goalNeg).resume(null, Long.MAX_VALUE, evaluationLimit);
    }

    /** A search that can be interrupted (LIMIT at a work bound, TIMEOUT at the deadline) and resumed where it stopped. */
    Run start(int[] init, int[] goalPos, int[] goalNeg) {
        return new Run(init, goalPos, goalNeg);
    }

    final class Run {
        private final int[] init;
        private final int[] goalPos;
        private final int[] goalNeg;
        private final StateSpace space = new StateSpace();
        private final int nq = landmarks == null ? 2 : landmarkQueueOverAll ? 4 : 3;
        private final LongHeap[] queues = new LongHeap[nq];
        private final int[] priority = new int[nq];
        private long[][] accepted = landmarks == null ? null : new long[1024][];
        private long expanded;
        private long evaluated;
        private int bestFf = Integer.MAX_VALUE;
        private int bestLm = Integer.MAX_VALUE;
        /** The FF value of the initial state (-1 before it is evaluated). */
        private int initialFf = -1;
        /** Evaluations when either heuristic last reached a new best value. */
        private long lastProgress;

        private Run(int[] init, int[] goalPos, int[] goalNeg) {
            this.init = init;
            this.goalPos = goalPos;
            this.goalNeg = goalNeg;
            for (int i = 0; i < nq; i++) queues[i] = new LongHeap();
            queues[0].push(0, entry(-1, -1));
        }

        long evaluated() {
            return evaluated;
        }

        /**
         * How far the FF value has come down from the initial state's towards 0 (0 to 1): a greedy search
         * on a task without dead ends (logistics, transport) finds its plan about where this reaches 1,
         * so the work spent divided by it foretells the work a plan needs.
         */
        double progress() {
            if (initialFf <= 0 || bestFf == Integer.MAX_VALUE) return 0;
            return (initialFf - bestFf) / (double) initialFf;
        }

        /** Evaluations when a heuristic last reached a new best value (its plateau began there). */
        long lastProgress() {
            return lastProgress;
        }

        /**
         * Continues until a plan, exhaustion, the deadline (TIMEOUT), {@code meter} reaching
         * {@code workUntil} or {@code evaluationLimit} evaluations in all (LIMIT); {@code meter} may be null.
         */
        BestFirstSearch.Result resume(WorkMeter meter, long workUntil, long evaluationLimit) {
            while (true) {
                int qi = -1;
                for (int i = 0; i < nq; i++) {
                    if (!queues[i].isEmpty() && (qi < 0 || priority[i] < priority[qi])) qi = i;
                }
                if (qi < 0) break;
                // checked before the queue's turn is counted, so a resumed search continues exactly
                if ((evaluated & 7) == 0 && System.nanoTime() > deadline) {
                    return new BestFirstSearch.Result(BestFirstSearch.Outcome.TIMEOUT, null, null, expanded, evaluated);
                }
                if (evaluated >= evaluationLimit || (meter != null && meter.now() >= workUntil)) {
                    return new BestFirstSearch.Result(BestFirstSearch.Outcome.LIMIT, null, null, expanded, evaluated);
                }
                priority[qi]++;
                int e = queues[qi].pop();
                int parent = entryParent[e];
                int op = entryOp[e];
                int[] state = parent < 0 ? init : successors.apply(space.state(parent), op);
                int g = parent < 0 ? 0 : space.g(parent) + 1;
                if (g >= lengthBound) continue;
                int node = space.find(state);
                int h;
                if (node >= 0) {
                    // greedy: the first path stays; weighted: a shorter one reopens the state, values kept
                    if (weight == 0 || g >= space.g(node)) continue;
                    space.reparent(node, parent, op, g);
                    h = space.h(node);
                    if (h == FfHeuristic.INFINITE) continue;
                    heuristic.evaluate(state, goalPos); // its helpful actions (counted as an evaluation)
                    evaluated++;
                } else {
                    h = heuristic.evaluate(state, goalPos);
                    evaluated++;
                    node = space.add(state, parent, op, g, h);
                    if (h == FfHeuristic.INFINITE) continue;
                    if (Successors.satisfies(state, goalPos, goalNeg)) {
                        return new BestFirstSearch.Result(BestFirstSearch.Outcome.FOUND, space.path(node), state, expanded, evaluated);
                    }
                }
                expanded++;
                if (initialFf < 0) initialFf = h;
                boolean progress = false;
                if (h < bestFf) {
                    bestFf = h;
                    progress = true;
                }
                int hl = 0;
                if (landmarks != null) {
                    if (node >= accepted.length) accepted = Arrays.copyOf(accepted, accepted.length * 2);
                    accepted[node] = landmarks.accept(parent < 0 ? null : accepted[parent], state);
                    hl = landmarks.value(accepted[node], state);
                    if (hl < bestLm) {
                        bestLm = hl;
                        progress = true;
                    }
                }
                if (progress) {
                    lastProgress = evaluated;
                    priority[1] -= 1000;
                    if (nq > 2) priority[2] -= 1000;
                }
                int nh = heuristic.helpfulCount();
                int[] helpful = new int[nh];
                for (int i = 0; i < nh; i++) helpful[i] = heuristic.helpful(i);
                Arrays.sort(helpful);
                int n = successors.applicable(state);
                for (int i = 0; i < n; i++) {
                    int o = successors.get(i);
                    int id = entry(node, o);
                    boolean preferred = Arrays.binarySearch(helpful, o) >= 0;
                    int kf = weight == 0 ? h : key(g + 1, h);
                    int kl = weight == 0 ? hl : key(g + 1, hl);
                    queues[0].push(kf, id);
                    if (preferred) queues[1].push(kf, id);
                    if (preferred && nq > 2) queues[2].push(kl, id);
                    if (nq == 4) queues[3].push(kl, id);
                }
            }
            return new BestFirstSearch.Result(BestFirstSearch.Outcome.EXHAUSTED, null, null, expanded, evaluated);
        }

        private int key(int g, int h) {
            return (int) Math.min(Integer.MAX_VALUE, g + (long) weight * h);
        }
    }
}
