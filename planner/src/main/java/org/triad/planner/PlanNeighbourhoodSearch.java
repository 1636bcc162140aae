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
    /** Transitions kept per round at most (two ints each, 64 MB): wide tasks stop at fewer states. */
    static final int MAX_EDGES = 8_000_000;

    private final Successors successors;
    private final int maxStates;
    private long deadline;
    private WorkMeter meter;
    private long workUntil = Long.MAX_VALUE;
    private boolean timedOut;
    private boolean complete;
    /** The last round stopped at {@link #MAX_EDGES}: a larger bound would explore the same states. */
    private boolean edgeLimited;
    /** The neighbourhood size of the next round: a later call goes on where the last one stopped. */
    private int bound;

    /** @param maxStates the largest neighbourhood tried (memory bound) */
    PlanNeighbourhoodSearch(Successors successors, int maxStates) {
        this.successors = successors;
        this.maxStates = maxStates;
        this.bound = Math.min(FIRST_BOUND, maxStates);
    }

    /** Whether the last {@link #improve} stopped at the deadline (its plan is the best so far, not the end of its budget). */
    boolean timedOut() {
        return timedOut;
    }

    /** Makes later calls stop once {@code meter} reaches {@code until}: the budget that decides the plan, not time. */
    PlanNeighbourhoodSearch limitWork(WorkMeter meter, long until) {
        this.meter = meter;
        this.workUntil = until;
        return this;
    }

    /** Whether the last {@link #improve} explored the whole reachable space (its result is then a shortest plan). */
    boolean provedShortest() {
        return complete;
    }

    /**
     * A plan no longer than {@code plan} (which must be valid) reaching the goal from {@code init};
     * the best so far at {@code deadlineNanos} ({@link System#nanoTime()}).
     */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan, long deadlineNanos) {
        return improve(init, goalPos, goalNeg, plan, deadlineNanos, true);
    }

    /** As {@link #improve(int[], int[], int[], int[], long)}; without {@code grow}, stops at the first round that does not help. */
    int[] improve(int[] init, int[] goalPos, int[] goalNeg, int[] plan, long deadlineNanos, boolean grow) {
        deadline = deadlineNanos;
        complete = false;
        timedOut = false;
        if (plan.length == 0) return plan;
        while (!(timedOut = System.nanoTime() >= deadline) && !workSpent()) {
            int[] shorter = round(init, goalPos, goalNeg, plan, bound);
            if (shorter == null) return plan; // deadline or work bound
            if (complete) return shorter;
            if (shorter.length < plan.length) {
                plan = shorter;
            } else {
                if (!grow || bound >= maxStates || edgeLimited) return plan;
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
        fifo = push(fifo, tail++, hood.add(state, -1, -1, 0, 0));
        for (int o : plan) {
            state = successors.apply(state, o);
            if (hood.find(state) < 0) fifo = push(fifo, tail++, hood.add(state, -1, -1, 0, 0));
        }
        int sources = tail;
        // multi-source breadth-first: every plan state's neighbourhood grows one layer at a time; the
        // edges of expanded states are kept (node i's in [edgeStart[i], edgeStart[i + 1])), and the
        // plan's states are always expanded, so the plan's own path is among them
        int[] edgeStart = new int[fifo.length + 1];
        int[] edgeTo = new int[1024];
        int[] edgeOp = new int[1024];
        int edges = 0;
        int head = 0;
        while (head < tail && (head < sources || (hood.size() < bound && edges < MAX_EDGES))) {
            if ((head & 63) == 0) {
                if (workSpent()) return null;
                if (System.nanoTime() > deadline) {
                    timedOut = true;
                    return null;
                }
            }
            int node = fifo[head++];
            int[] s = hood.state(node);
            int n = successors.applicable(s);
            int[] ops = new int[n];
            for (int i = 0; i < n; i++) ops[i] = successors.get(i);
            for (int o : ops) {
                int[] c = successors.apply(s, o);
                int child = hood.find(c);
                if (child < 0) {
                    child = hood.add(c, -1, -1, 0, 0);
                    fifo = push(fifo, tail++, child);
                }
                if (edges == edgeTo.length) {
                    edgeTo = java.util.Arrays.copyOf(edgeTo, edges * 2);
                    edgeOp = java.util.Arrays.copyOf(edgeOp, edges * 2);
                }
                edgeTo[edges] = child;
                edgeOp[edges++] = o;
            }
            if (node + 1 >= edgeStart.length) edgeStart = java.util.Arrays.copyOf(edgeStart, Math.max(edgeStart.length * 2, node + 2));
            edgeStart[node + 1] = edges;
        }
        complete = head == tail;
        edgeLimited = edges >= MAX_EDGES;
        // nodes were expanded in id order 0 .. head-1 (the fifo holds ids in creation order)
        return shortestPath(hood, head, edgeStart, edgeTo, edgeOp, goalPos, goalNeg);
    }

    private boolean workSpent() {
        return meter != null && meter.now() >= workUntil;
    }

    private static int[] push(int[] fifo, int at, int node) {
        if (at == fifo.length) fifo = java.util.Arrays.copyOf(fifo, at * 2);
        fifo[at] = node;
        return fifo;
    }

    /** Breadth-first from the initial state (node 0) over the kept edges. */
    private int[] shortestPath(StateSpace hood, int expanded, int[] edgeStart, int[] edgeTo, int[] edgeOp, int[] goalPos, int[] goalNeg) {
        int size = hood.size();
        int[] parent = new int[size];
        int[] via = new int[size];
        java.util.Arrays.fill(parent, -2);
        parent[0] = -1;
        int[] fifo = new int[size];
        int tail = 0;
        fifo[tail++] = 0;
        for (int head = 0; head < tail; head++) {
            int node = fifo[head];
            if (Successors.satisfies(hood.state(node), goalPos, goalNeg)) {
                int len = 0;
                for (int x = node; parent[x] >= 0; x = parent[x]) len++;
                int[] out = new int[len];
                for (int x = node; parent[x] >= 0; x = parent[x]) out[--len] = via[x];
                return out;
            }
            if (node >= expanded) continue;
            for (int e = edgeStart[node], end = edgeStart[node + 1]; e < end; e++) {
                int c = edgeTo[e];
                if (parent[c] != -2) continue;
                parent[c] = node;
                via[c] = edgeOp[e];
                fifo[tail++] = c;
            }
        }
        throw new IllegalStateException("the plan's own path lies in its neighbourhood");
    }
}
