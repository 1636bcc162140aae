package org.triad.planner;

/**
 * The FF heuristic with h^add best supporters, as Fast Downward computes it: the relaxed plan is
 * extracted through, for each fact, the achiever whose preconditions have the least summed
 * relaxed cost (a Dijkstra over facts), not the first achiever by relaxed level. Level-first
 * supporters pick whatever achiever the breadth-first exploration meets first, often one whose
 * preconditions take a detour of their own (in mystery p10 the heuristic then grows along Fast
 * Downward's 8-step plan and its first steps are not helpful); summed costs prefer achievers
 * that share what is already needed. It relaxes the task as {@link FfHeuristic} does ({@link RelaxedOps}:
 * conditional effects, complements of facts needed false, derived-predicate rules). Costs more per evaluation (a bucket queue), so {@link FirstPlanPortfolio}
 * uses it in one configuration beside the level-based one.
 */
final class AdditiveFfHeuristic extends FfHeuristic {
    /** Summed costs can grow fast; beyond this they are all alike (and the bucket array stays small). */
    static final int MAX_COST = 1 << 16;

    private final RelaxedOps t;
    private final int[] cost;
    private final int[] factEpoch;
    private final int[] done;
    private final int[] supporter;
    /** Per operator, interleaved for locality: [3o] epoch of last touch, [3o+1] unmet preconditions, [3o+2] summed cost. */
    private final int[] opState;
    private final int[] goalMark;
    /** Bucket queue by cost (Dijkstra's pops are monotone): facts of cost c in bucket[c][0 .. bucketSize[c]). */
    private int[][] bucket = new int[64][];
    private int[] bucketSize = new int[64];
    private int current;
    private int highest;
    private int epoch;

    AdditiveFfHeuristic(SearchTask task) {
        super(task);
        this.t = task.relaxed;
        int nf = t.size;
        int no = t.count;
        cost = new int[nf];
        factEpoch = new int[nf];
        done = new int[nf];
        supporter = new int[nf];
        opState = new int[3 * no];
        goalMark = new int[nf];
    }

    private void reach(int f, int c, int op) {
        if (factEpoch[f] != epoch || c < cost[f]) {
            factEpoch[f] = epoch;
            cost[f] = c;
            supporter[f] = op;
            push(c, f);
        }
    }

    private void push(int c, int f) {
        if (c >= bucket.length) {
            int n = Math.max(c + 1, 2 * bucket.length);
            bucket = java.util.Arrays.copyOf(bucket, n);
            bucketSize = java.util.Arrays.copyOf(bucketSize, n);
        }
        int[] b = bucket[c];
        if (b == null) b = bucket[c] = new int[16];
        if (bucketSize[c] == b.length) b = bucket[c] = java.util.Arrays.copyOf(b, 2 * b.length);
        b[bucketSize[c]++] = f;
        if (c > highest) highest = c;
    }

    /** The next fact by cost, -1 when none is left. */
    private int pop() {
        while (current <= highest) {
            if (bucketSize[current] > 0) return bucket[current][--bucketSize[current]];
            current++;
        }
        return -1;
    }

    @Override
    int evaluate(int[] state, int[] goals) {
        epoch++;
        extraction.clear();
        for (int c = 0; c <= highest; c++) bucketSize[c] = 0;
        current = 0;
        highest = 0;
        for (int f : state) reach(f, 0, -1);
        work += state.length;
        // a fact the state lacks makes its complement true (negative preconditions and conditions)
        for (int k = 0; k < t.negFacts.length; k++) {
            if (factEpoch[t.negFacts[k]] != epoch) reach(t.numFacts + k, 0, -1);
        }
        int missing = 0;
        for (int g : goals) {
            if (factEpoch[g] != epoch) {
                if (goalMark[g] != epoch) missing++;
                goalMark[g] = epoch;
            }
        }
        if (missing == 0) return 0;
        for (int o : t.noPre) for (int a : t.add[o]) reach(a, 1, o);
        while (missing > 0) {
            int f = pop();
            if (f < 0) break;
            if (done[f] == epoch) continue;
            done[f] = epoch;
            if (goalMark[f] == epoch) missing--;
            int c = cost[f];
            work += preStart[f + 1] - preStart[f] + 1;
            for (int i = preStart[f], end = preStart[f + 1]; i < end; i++) {
                int o = preOps[i];
                int s3 = 3 * o;
                int oc;
                if (preCount[o] == 1) {
                    oc = c + 1;
                } else {
                    if (opState[s3] != epoch) {
                        opState[s3] = epoch;
                        opState[s3 + 1] = preCount[o] - 1;
                        opState[s3 + 2] = c;
                        continue;
                    }
                    opState[s3 + 2] += c;
                    if (--opState[s3 + 1] != 0) continue;
                    oc = Math.min(opState[s3 + 2] + 1, MAX_COST);
                }
                for (int j = addStart[o], aend = addStart[o + 1]; j < aend; j++) {
                    int a = addFacts[j];
                    if (done[a] != epoch) reach(a, oc, o);
                }
            }
        }
        if (missing > 0) return INFINITE;
        return extraction.extract(goals, cost, supporter);
    }
}
