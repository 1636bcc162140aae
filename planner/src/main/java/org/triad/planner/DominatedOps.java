package org.triad.planner;

import java.util.Arrays;

/**
 * Operators a cheapest plan never needs, for the cost search: an operator whose effects beyond a
 * kept operator's touch nothing the kept operators or the goal look at (a courier's {@code guide} of a
 * person along a corridor, where {@code move} along it costs as much and the goal needs no person
 * anywhere), or one that changes nothing they look at at all ({@code startFollowing} once {@code walk}
 * is gone). Leaving them out shrinks the states A* has to prove (a delivery's states no longer come
 * with every place a person could be walked to).
 * <p>
 * <b>Why it is safe.</b> Let K be the kept operators, R the facts that K's preconditions and the goal
 * need true, N those they need false. An operator o is left out when either it adds nothing in R and
 * deletes nothing in N (useless), or a kept d dominates it: d needs no more than o (positive and
 * negative preconditions), adds no more, deletes no more, costs no more, and o's further adds miss R
 * and its further deletes miss N. Replacing each left-out operator of a plan by its dominator (or
 * dropping it when useless) keeps, after every step, each fact of R true where it was true and each
 * fact of N false where it was false, so the plan stays valid, costs no more and has no more steps:
 * the reduced task has the same cheapest plans, and of them, the same fewest steps. The sets are a
 * fixpoint: start with every operator left out; an operator that is not useless against the current K
 * is kept, or rather its dominator is, when it has one (in operator order, so the result is
 * deterministic), until a pass changes nothing; every operator left out is then useless or dominated by
 * a kept one against the final K.
 * Not applied with conditional effects or derived predicates.
 */
final class DominatedOps {
    /** Past this many operators the analysis is skipped (it pays on robots' tasks, which are small). */
    static final int MAX_OPS = 20_000;
    /** Dominator candidates examined per operator. */
    private static final int MAX_CANDIDATES = 64;

    private DominatedOps() { }

    /**
     * Per operator, whether it is left out; null when none is or the analysis does not apply.
     * {@code cost} gives each operator's cost in comparable units.
     */
    static boolean[] of(SearchTask t, long[] cost, int[] goalPos, int[] goalNeg) {
        if (t.hasConditionalEffects || t.axioms != null || t.ops.length > MAX_OPS) return null;
        int no = t.ops.length;
        int nf = t.numFacts;
        // ops by added fact, to find dominators: d adds no more than o, so d (if it adds anything) adds one of o's facts
        int[] count = new int[nf];
        for (int o = 0; o < no; o++) for (int a : t.add[o]) count[a]++;
        int[][] addOf = new int[nf][];
        for (int f = 0; f < nf; f++) addOf[f] = new int[count[f]];
        Arrays.fill(count, 0);
        for (int o = 0; o < no; o++) for (int a : t.add[o]) addOf[a][count[a]++] = o;

        boolean[] out = new boolean[no];
        Arrays.fill(out, true);
        int[] needTrue = new int[nf];
        int[] needFalse = new int[nf];
        for (int g : goalPos) needTrue[g]++;
        for (int g : goalNeg) needFalse[g]++;
        boolean changed = true;
        while (changed) {
            changed = false;
            for (int o = 0; o < no; o++) {
                if (!out[o] || useless(t, o, needTrue, needFalse)) continue;
                // a dominator stands in for o: kept from now on (keeping one more operator is always safe)
                int d = dominator(t, o, cost, addOf, out, needTrue, needFalse);
                int keep = d >= 0 ? d : o;
                if (!out[keep]) continue;
                out[keep] = false;
                for (int p : t.pre[keep]) needTrue[p]++;
                for (int p : t.neg[keep]) needFalse[p]++;
                changed = true;
            }
        }
        for (boolean b : out) if (b) return out;
        return null;
    }

    private static boolean useless(SearchTask t, int o, int[] needTrue, int[] needFalse) {
        for (int a : t.add[o]) if (needTrue[a] > 0) return false;
        for (int d : t.del[o]) if (needFalse[d] > 0) return false;
        return true;
    }

    /** An operator dominating o, a kept one if there is one, else the first; -1 if none. */
    private static int dominator(SearchTask t, int o, long[] cost, int[][] addOf, boolean[] out, int[] needTrue, int[] needFalse) {
        int examined = 0;
        int first = -1;
        for (int a : t.add[o]) {
            for (int d : addOf[a]) {
                if (d == o) continue;
                if (++examined > MAX_CANDIDATES) return first;
                if (!dominates(t, d, o, cost, needTrue, needFalse)) continue;
                if (!out[d]) return d;
                if (first < 0) first = d;
            }
        }
        return first;
    }

    private static boolean dominates(SearchTask t, int d, int o, long[] cost, int[] needTrue, int[] needFalse) {
        if (cost[d] > cost[o]) return false;
        if (!subset(t.pre[d], t.pre[o]) || !subset(t.neg[d], t.neg[o]) || !subset(t.add[d], t.add[o]) || !subset(t.del[d], t.del[o])) return false;
        for (int a : t.add[o]) if (needTrue[a] > 0 && Arrays.binarySearch(t.add[d], a) < 0) return false;
        for (int x : t.del[o]) if (needFalse[x] > 0 && Arrays.binarySearch(t.del[d], x) < 0) return false;
        return true;
    }

    /** Whether sorted {@code a} is contained in sorted {@code b}. */
    static boolean subset(int[] a, int[] b) {
        int j = 0;
        for (int x : a) {
            while (j < b.length && b[j] < x) j++;
            if (j == b.length || b[j] != x) return false;
            j++;
        }
        return true;
    }
}
