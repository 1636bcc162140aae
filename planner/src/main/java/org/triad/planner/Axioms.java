package org.triad.planner;

import java.util.Arrays;
import java.util.List;

/**
 * Ground rules of derived predicates: after every action (and in the initial state) the derived
 * facts are recomputed from the basic ones, stratum by stratum, each stratum a least fixpoint
 * (counter-based, like relaxed reachability: a rule fires when its last positive condition becomes
 * true; its negative conditions are basic or lower-stratum facts, final by then).
 */
final class Axioms {
    final int[][] pre;
    final int[][] neg;
    final int[] head;
    /** Rules of stratum s are {@code stratumStart[s] .. stratumStart[s+1]}. */
    private final int[] stratumStart;
    final boolean[] derivedFact;
    private final int[][] preOf;
    private final int[] mark;
    private final int[] count;
    private final int[] countEpoch;
    private int epoch;

    /** {@code rules} with their strata; {@code derivedFact} marks the facts rules define. */
    Axioms(List<GroundOp> rules, List<Integer> strata, boolean[] derivedFact) {
        int n = rules.size();
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> Integer.compare(strata.get(a), strata.get(b)));
        pre = new int[n][];
        neg = new int[n][];
        head = new int[n];
        int maxStratum = 0;
        for (int s : strata) maxStratum = Math.max(maxStratum, s);
        stratumStart = new int[maxStratum + 2];
        int[] perStratum = new int[maxStratum + 1];
        for (int i = 0; i < n; i++) {
            GroundOp r = rules.get(order[i]);
            pre[i] = r.pre();
            neg[i] = r.neg();
            head[i] = r.add()[0];
            perStratum[strata.get(order[i])]++;
        }
        for (int s = 0; s <= maxStratum; s++) stratumStart[s + 1] = stratumStart[s] + perStratum[s];
        this.derivedFact = derivedFact;
        int nf = derivedFact.length;
        int[] c = new int[nf];
        for (int[] p : pre) for (int f : p) c[f]++;
        preOf = new int[nf][];
        for (int f = 0; f < nf; f++) preOf[f] = new int[c[f]];
        int[] fill = new int[nf];
        for (int i = 0; i < n; i++) for (int f : pre[i]) preOf[f][fill[f]++] = i;
        mark = new int[nf];
        count = new int[n];
        countEpoch = new int[n];
    }

    /** The state with its derived facts recomputed from its basic facts (sorted). */
    synchronized int[] close(int[] state) {
        epoch++;
        int[] out = new int[state.length + 16];
        int n = 0;
        for (int f : state) {
            if (f < derivedFact.length && derivedFact[f]) continue;
            if (f < mark.length) mark[f] = epoch;
            out[n++] = f;
        }
        int[] queue = new int[16];
        for (int s = 0; s + 1 < stratumStart.length; s++) {
            int qh = 0;
            int qt = 0;
            int from = stratumStart[s];
            int to = stratumStart[s + 1];
            // count first, fire after: a head marked while counting would be counted twice
            int ready = 0;
            int[] readyRules = new int[Math.max(1, to - from)];
            for (int a = from; a < to; a++) {
                boolean blocked = false;
                for (int f : neg[a]) if (mark[f] == epoch) { blocked = true; break; }
                if (blocked) continue;
                int missing = 0;
                for (int f : pre[a]) if (mark[f] != epoch) missing++;
                count[a] = missing;
                countEpoch[a] = epoch;
                if (missing == 0) readyRules[ready++] = a;
            }
            for (int i = 0; i < ready; i++) {
                int h = head[readyRules[i]];
                if (mark[h] == epoch) continue;
                mark[h] = epoch;
                if (n == out.length) out = Arrays.copyOf(out, n * 2);
                out[n++] = h;
                if (qt == queue.length) queue = Arrays.copyOf(queue, qt * 2);
                queue[qt++] = h;
            }
            while (qh < qt) {
                int f = queue[qh++];
                for (int a : preOf[f]) {
                    if (a < from || a >= to || countEpoch[a] != epoch) continue;
                    if (--count[a] != 0) continue;
                    int h = head[a];
                    if (mark[h] == epoch) continue;
                    mark[h] = epoch;
                    if (n == out.length) out = Arrays.copyOf(out, n * 2);
                    out[n++] = h;
                    if (qt == queue.length) queue = Arrays.copyOf(queue, qt * 2);
                    queue[qt++] = h;
                }
            }
        }
        int[] r = Arrays.copyOf(out, n);
        Arrays.sort(r);
        return r;
    }
}
