package org.triad.planner;

/**
 * Plan Neighbourhood Graph Search (Nakhost and Müller 2010): the states of a valid plan are the
 * sources of a breadth-first exploration bounded by a number of states; the shortest path from the
 * initial state to a goal state inside the explored neighbourhood replaces the plan. The plan's own
 * path lies in the neighbourhood, so the result is never longer; it is repeated on the new plan while
 * it improves, and with a doubled bound when it does not, until the bound, the state limit or the
 * deadline is reached, or the neighbourhood is the whole reachable space (then the plan is shortest).
 * Unit action costs: it minimises the number of actions.
 */
final class PlanNeighbourhoodSearch {
    /** States explored around the plan in the first round. */
    static final int FIRST_BOUND = 1000;

    private final Successors successors;
    private final long deadline;
    private final int maxStates;
    private boolean complete;

    /**
     * @param maxStates the largest neighbourhood tried (memory bound)
     * @param deadlineNanos {@link System#nanoTime()} after which the best plan so far is returned
     */
    PlanNeighbourhoodSearch(Successors successors, int maxStates, long deadlineNanos) {
        this.successors = successors;
        this.maxStates = maxStates;
        this.deadline = deadlineNanos;
    }

    /** Whether the last {@link #improve} explored the whole reachable space (its result is then a shortest plan). */
    boolean provedShortest() {
        return complete;
    }

    /** A plan no longer than {@code plan} (which must be valid) reaching the goal from {@code init}. */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        complete = false;
        int bound = Math.min(FIRST_BOUND, maxStates);
        while (System.nanoTime() < deadline) {
            int[] shorter = round(init, goalPos, goalNeg, plan, bound);
            if (shorter == null) return plan; // deadline
            if (complete) return shorter;
            if (shorter.length < plan.length) {
                plan = shorter;
            } else {
                if (bound >= maxStates) return plan;
                bound = (int) Math.min((long) bound * 2, maxStates);
            }
        }
        return plan;
    }

    /** One round with a neighbourhood of about {@code bound} states; null at the deadline. */
    private int[] round(int[] init, int[] goalPos, int[] goalNeg, int[] plan, int bound) {
        StateSpace hood = new StateSpace();
        int[] fifo = new int[Math.max(16, plan.length + 1)];
        int tail = 0;
        int[] state = init;
        if (hood.find(state) < 0) fifo = push(fifo, tail++, hood.add(state, -1, -1, 0, 0));
        for (int o : plan) {
            state = successors.apply(state, o);
            if (hood.find(state) < 0) fifo = push(fifo, tail++, hood.add(state, -1, -1, 0, 0));
        }
        // multi-source breadth-first: every plan state's neighbourhood grows one layer at a time
        int head = 0;
        while (head < tail && hood.size() < bound) {
            if ((head & 63) == 0 && System.nanoTime() > deadline) return null;
            int[] s = hood.state(fifo[head++]);
            int n = successors.applicable(s);
            int[] ops = new int[n];
            for (int i = 0; i < n; i++) ops[i] = successors.get(i);
            for (int o : ops) {
                int[] c = successors.apply(s, o);
                if (hood.find(c) >= 0) continue;
                fifo = push(fifo, tail++, hood.add(c, -1, -1, 0, 0));
            }
        }
        complete = head == tail;
        return shortestPath(hood, init, goalPos, goalNeg);
    }

    private static int[] push(int[] fifo, int at, int node) {
        if (at == fifo.length) fifo = java.util.Arrays.copyOf(fifo, at * 2);
        fifo[at] = node;
        return fifo;
    }

    /** Breadth-first from the initial state over the neighbourhood's states only. */
    private int[] shortestPath(StateSpace hood, int[] init, int[] goalPos, int[] goalNeg) {
        StateSpace seen = new StateSpace();
        int root = seen.add(init, -1, -1, 0, 0);
        if (Successors.satisfies(init, goalPos, goalNeg)) return new int[0];
        int[] fifo = new int[64];
        int tail = 0;
        fifo[tail++] = root;
        for (int head = 0; head < tail; head++) {
            if ((head & 63) == 0 && System.nanoTime() > deadline) return null;
            int node = fifo[head];
            int[] s = seen.state(node);
            int n = successors.applicable(s);
            int[] ops = new int[n];
            for (int i = 0; i < n; i++) ops[i] = successors.get(i);
            for (int o : ops) {
                int[] c = successors.apply(s, o);
                if (hood.find(c) < 0 || seen.find(c) >= 0) continue;
                int child = seen.add(c, node, o, seen.g(node) + 1, 0);
                if (Successors.satisfies(c, goalPos, goalNeg)) return seen.path(child);
                fifo = push(fifo, tail++, child);
            }
        }
        throw new IllegalStateException("the plan's own path lies in its neighbourhood");
    }
}
