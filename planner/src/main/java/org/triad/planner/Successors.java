package org.triad.planner;

import java.util.Arrays;

/** Applicable operators and successor states over sorted fact arrays. */
final class Successors {
    private final SearchTask t;
    private final int[] mark;
    private int epoch;
    private int[] buf = new int[64];
    private int count;
    /**
     * Operators that would have been considered had their first precondition triggered the test (the
     * count this meter has always had, so budgets and plans stay as they were) and facts written,
     * over all calls: machine-independent effort ({@link WorkMeter}).
     */
    private long work;

    Successors(SearchTask t) {
        this.t = t;
        mark = new int[t.numFacts];
    }

    /** Fills the applicable operators of the state, ascending by id; returns their number. */
    int applicable(int[] state) {
        epoch++;
        for (int f : state) mark[f] = epoch;
        count = 0;
        work += t.noPre.length;
        for (int o : t.noPre) consider(o);
        for (int f : state) {
            work += t.firstPreCount[f];
            for (int o : t.triggeredBy[f]) consider(o);
        }
        Arrays.sort(buf, 0, count);
        return count;
    }

    private void consider(int o) {
        for (int p : t.pre[o]) if (mark[p] != epoch) return;
        for (int p : t.neg[o]) if (mark[p] == epoch) return;
        if (count == buf.length) buf = Arrays.copyOf(buf, count * 2);
        buf[count++] = o;
    }

    long work() {
        return work;
    }

    int get(int i) {
        return buf[i];
    }

    boolean isApplicable(int[] state, int o) {
        for (int p : t.pre[o]) if (Arrays.binarySearch(state, p) < 0) return false;
        for (int p : t.neg[o]) if (Arrays.binarySearch(state, p) >= 0) return false;
        return true;
    }

    int[] apply(int[] state, int o) {
        int[] del = t.del[o];
        int[] add = t.add[o];
        GroundOp.When[] when = t.when[o];
        if (when != null) {
            // every condition is evaluated in the state before the operator; then deletes, then adds
            for (GroundOp.When w : when) {
                if (!satisfies(state, w.pre(), w.neg())) continue;
                add = Grounder.union(add, w.add());
                del = Grounder.union(del, w.del());
            }
            del = Grounder.minus(del, add);
        }
        work += state.length + add.length;
        int[] out = new int[state.length + add.length];
        int n = 0;
        int i = 0;
        int j = 0;
        while (i < state.length || j < add.length) {
            int next;
            if (j >= add.length || (i < state.length && state[i] < add[j])) {
                next = state[i++];
                if (Arrays.binarySearch(del, next) >= 0) continue;
            } else if (i >= state.length || add[j] < state[i]) {
                next = add[j++];
            } else {
                next = state[i++];
                j++;
            }
            out[n++] = next;
        }
        int[] next = n == out.length ? out : Arrays.copyOf(out, n);
        return t.axioms == null ? next : t.axioms.close(next);
    }

    static boolean satisfies(int[] state, int[] goalPos, int[] goalNeg) {
        for (int g : goalPos) if (Arrays.binarySearch(state, g) < 0) return false;
        for (int g : goalNeg) if (Arrays.binarySearch(state, g) >= 0) return false;
        return true;
    }
}
