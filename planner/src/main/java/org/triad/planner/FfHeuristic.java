package org.triad.planner;

/**
 * The FF heuristic: a relaxed planning graph explored breadth-first from the state (ignoring
 * deletes and negative preconditions) until all goals are reached, then a relaxed plan extracted
 * backwards through first achievers. Its operators applicable in the state are the helpful actions.
 * Scratch arrays are reused and invalidated by an epoch counter, so an evaluation only touches the
 * part of the graph it explores. Conditional effects are relaxed as separate operators
 * ({@link RelaxedOps}); the value counts each operator of the relaxed plan once.
 */
class FfHeuristic {
    static final int INFINITE = Integer.MAX_VALUE;

    private final RelaxedOps t;
    private final boolean lastAchiever;
    /** The relaxed plan's extraction, shared with {@link AdditiveFfHeuristic}. */
    final RelaxedPlanExtraction extraction;
    private final int[] level;
    private final int[] factEpoch;
    private final int[] supporter;
    /** Per operator, interleaved for locality: [2o] = epoch of last touch, [2o+1] = unsatisfied preconditions. */
    private final int[] opState;
    /** Compressed rows ({@link RelaxedRows}), read by {@link AdditiveFfHeuristic} too. */
    final int[] preStart;
    final int[] preOps;
    final int[] preCount;
    final int[] addStart;
    final int[] addFacts;
    private final int[] factMark;
    private final int[] queue;
    private int epoch;
    /**
     * Work done so far: facts explored plus operator rows scanned, over all evaluations. A measure
     * of effort that does not depend on the machine or its load, so that budgets counted in it give
     * the same plan everywhere ({@link WorkMeter}).
     */
    long work;

    FfHeuristic(SearchTask task) {
        this(task, false);
    }

    /**
     * With {@code lastAchiever}, of the achievers that reach a fact at its level the one met last is
     * its supporter (the relaxed plan then runs through the preconditions reached last, the side Fast
     * Downward's last-in first-out h^add exploration takes), otherwise the first one met.
     */
    FfHeuristic(SearchTask task, boolean lastAchiever) {
        this.lastAchiever = lastAchiever;
        this.t = task.relaxed;
        int nf = t.size;
        int no = t.count;
        extraction = new RelaxedPlanExtraction(task);
        level = new int[nf];
        factEpoch = new int[nf];
        supporter = new int[nf];
        opState = new int[2 * no];
        RelaxedRows rows = new RelaxedRows(t);
        preStart = rows.preStart;
        preOps = rows.preOps;
        preCount = rows.preCount;
        addStart = rows.addStart;
        addFacts = rows.addFacts;
        factMark = new int[nf];
        queue = new int[nf];
    }

    /** {@link #work}, for callers outside the heuristic. */
    long work() {
        return work;
    }

    int helpfulCount() {
        return extraction.helpfulCount();
    }

    int helpful(int i) {
        return extraction.helpful(i);
    }

    /** Relaxed plan length, or {@link #INFINITE} when the goals are unreachable even relaxed. */
    int evaluate(int[] state, int[] goals) {
        epoch++;
        extraction.clear();
        int head = 0;
        int tail = 0;
        for (int f : state) {
            factEpoch[f] = epoch;
            level[f] = 0;
            supporter[f] = -1;
            queue[tail++] = f;
        }
        for (int k = 0; k < t.negFacts.length; k++) {
            if (factEpoch[t.negFacts[k]] == epoch) continue;
            int c = t.numFacts + k;
            factEpoch[c] = epoch;
            level[c] = 0;
            supporter[c] = -1;
            queue[tail++] = c;
        }
        int missing = 0;
        for (int g : goals) if (factEpoch[g] != epoch) missing++;
        if (missing == 0) return 0;
        for (int o : t.noPre) {
            for (int a : t.add[o]) {
                if (factEpoch[a] != epoch) {
                    factEpoch[a] = epoch;
                    level[a] = 1;
                    supporter[a] = o;
                    queue[tail++] = a;
                }
            }
        }
        // Goals reached count is checked when facts are reached, so we can stop early.
        int[] goalMark = factMark; // reused: marks goals with -epoch during exploration
        for (int g : goals) goalMark[g] = -epoch;
        for (int i = 0; i < tail; i++) {
            if (goalMark[queue[i]] == -epoch && level[queue[i]] > 0) missing--;
        }
        work += tail;
        while (head < tail && missing > 0) {
            int f = queue[head++];
            int lf = level[f];
            work += preStart[f + 1] - preStart[f] + 1;
            for (int i = preStart[f], end = preStart[f + 1]; i < end; i++) {
                int o = preOps[i];
                int pc = preCount[o];
                if (pc > 1) {
                    int s2 = o << 1;
                    if (opState[s2] != epoch) {
                        opState[s2] = epoch;
                        opState[s2 + 1] = pc - 1;
                        continue;
                    }
                    if (--opState[s2 + 1] != 0) continue;
                }
                for (int j = addStart[o], aend = addStart[o + 1]; j < aend; j++) {
                    int a = addFacts[j];
                    {
                        if (factEpoch[a] != epoch) {
                            factEpoch[a] = epoch;
                            level[a] = lf + 1;
                            supporter[a] = o;
                            queue[tail++] = a;
                            if (goalMark[a] == -epoch) missing--;
                        } else if (lastAchiever && level[a] == lf + 1) {
                            supporter[a] = o;
                        }
                    }
                }
            }
        }
        if (missing > 0) {
            for (int g : goals) goalMark[g] = 0;
            return INFINITE;
        }
        for (int g : goals) goalMark[g] = 0;
        return extraction.extract(goals, level, supporter);
    }

    /**
     * Of the candidate facts, the one fewest relaxed steps from {@code state}, the lowest fact id
     * among equally near ones (-1 if none is reachable): exploration stops at the first level that
     * reaches a candidate.
     */
    int nearest(int[] state, int[] candidates) {
        epoch++;
        int[] mark = factMark;
        for (int c : candidates) mark[c] = -epoch;
        int tail = 0;
        int found = -1;
        int foundLevel = INFINITE;
        for (int f : state) {
            factEpoch[f] = epoch;
            level[f] = 0;
            queue[tail++] = f;
            if (mark[f] == -epoch && (found < 0 || f < found)) {
                found = f;
                foundLevel = 0;
            }
        }
        for (int k = 0; k < t.negFacts.length; k++) {
            if (factEpoch[t.negFacts[k]] == epoch) continue;
            int c = t.numFacts + k;
            factEpoch[c] = epoch;
            level[c] = 0;
            queue[tail++] = c;
        }
        for (int o : t.noPre) {
            for (int a : t.add[o]) {
                if (factEpoch[a] != epoch) {
                    factEpoch[a] = epoch;
                    level[a] = 1;
                    queue[tail++] = a;
                    if (mark[a] == -epoch && foundLevel >= 1 && (found < 0 || a < found)) {
                        found = a;
                        foundLevel = 1;
                    }
                }
            }
        }
        work += tail;
        for (int head = 0; head < tail; head++) {
            int f = queue[head];
            int lf = level[f];
            if (lf + 1 > foundLevel) break;
            work += preStart[f + 1] - preStart[f] + 1;
            for (int i = preStart[f], end = preStart[f + 1]; i < end; i++) {
                int o = preOps[i];
                int pc = preCount[o];
                if (pc > 1) {
                    int s2 = o << 1;
                    if (opState[s2] != epoch) {
                        opState[s2] = epoch;
                        opState[s2 + 1] = pc - 1;
                        continue;
                    }
                    if (--opState[s2 + 1] != 0) continue;
                }
                for (int j = addStart[o], aend = addStart[o + 1]; j < aend; j++) {
                    int a = addFacts[j];
                    if (factEpoch[a] != epoch) {
                        factEpoch[a] = epoch;
                        level[a] = lf + 1;
                        queue[tail++] = a;
                        if (mark[a] == -epoch && (found < 0 || a < found)) {
                            found = a;
                            foundLevel = lf + 1;
                        }
                    }
                }
            }
        }
        for (int c : candidates) mark[c] = 0;
        return found;
    }
}
