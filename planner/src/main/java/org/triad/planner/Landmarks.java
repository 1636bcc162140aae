package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Fact landmarks found by back-chaining from the goals: a precondition shared by every achiever of
 * a landmark that can be applied before it (in the relaxed task without the landmark's achievers)
 * is itself a landmark, ordered greedy-necessarily before it. The landmark-count heuristic (as in
 * LAMA) counts landmarks not yet accepted on the path plus accepted ones required again.
 */
final class Landmarks {
    final int count;
    private final int[] factOf;
    private final int[] lmOfFact;
    private final boolean[] goal;
    /** For landmark l: the landmarks that must be true right before l is first achieved ... and after. */
    private final int[][] children;
    private final int words;
    private final int[] mark;
    private int epoch;

    Landmarks(SearchTask task, int[] init, int[] goalPos, long deadline) {
        // over the relaxed operators: a conditional achiever needs its condition too
        RelaxedOps t = task.relaxed;
        int nf = t.size;
        int[] relaxedInit = t.initial(init);
        int[][] addOf = invert(t.add, nf);
        lmOfFact = new int[nf];
        Arrays.fill(lmOfFact, -1);
        List<Integer> facts = new ArrayList<>();
        List<List<Integer>> kids = new ArrayList<>();
        boolean[] inInit = new boolean[nf];
        for (int f : init) inInit[f] = true;
        for (int g : goalPos) add(g, facts, kids);
        ArrayList<Integer> queue = new ArrayList<>(facts);
        boolean[] reach = new boolean[nf];
        int[] unsat = new int[t.count];
        int[] fifo = new int[nf];
        for (int qi = 0; qi < queue.size() && System.nanoTime() < deadline; qi++) {
            int l = queue.get(qi);
            if (inInit[l]) continue;
            boolean[] excluded = new boolean[t.count];
            for (int o : addOf[l]) excluded[o] = true;
            relaxedReach(t, relaxedInit, excluded, reach, unsat, fifo);
            int[] shared = null;
            for (int o : addOf[l]) {
                boolean possible = true;
                for (int p : t.pre[o]) if (!reach[p]) { possible = false; break; }
                if (!possible) continue;
                shared = shared == null ? t.pre[o].clone() : intersect(shared, t.pre[o]);
            }
            if (shared == null) continue;
            int lmL = lmOfFact[l];
            for (int p : shared) {
                if (p >= task.numFacts) continue; // a complement: never in a state, so never accepted
                boolean fresh = lmOfFact[p] < 0;
                int lp = add(p, facts, kids);
                if (!kids.get(lp).contains(lmL)) kids.get(lp).add(lmL);
                if (fresh) queue.add(p);
            }
        }
        count = facts.size();
        factOf = facts.stream().mapToInt(Integer::intValue).toArray();
        goal = new boolean[count];
        for (int g : goalPos) goal[lmOfFact[g]] = true;
        children = new int[count][];
        for (int i = 0; i < count; i++) children[i] = kids.get(i).stream().mapToInt(Integer::intValue).toArray();
        words = (count + 63) >>> 6;
        mark = new int[nf];
    }

    private int add(int fact, List<Integer> facts, List<List<Integer>> kids) {
        if (lmOfFact[fact] >= 0) return lmOfFact[fact];
        lmOfFact[fact] = facts.size();
        facts.add(fact);
        kids.add(new ArrayList<>());
        return facts.size() - 1;
    }

    private static void relaxedReach(RelaxedOps t, int[] init, boolean[] excluded, boolean[] reach, int[] unsat, int[] fifo) {
        Arrays.fill(reach, false);
        for (int o = 0; o < unsat.length; o++) unsat[o] = t.pre[o].length;
        int head = 0;
        int tail = 0;
        for (int f : init) if (!reach[f]) { reach[f] = true; fifo[tail++] = f; }
        for (int o : t.noPre) {
            if (excluded[o]) continue;
            for (int a : t.add[o]) if (!reach[a]) { reach[a] = true; fifo[tail++] = a; }
        }
        while (head < tail) {
            int f = fifo[head++];
            for (int o : t.preOf[f]) {
                if (--unsat[o] == 0 && !excluded[o]) {
                    for (int a : t.add[o]) if (!reach[a]) { reach[a] = true; fifo[tail++] = a; }
                }
            }
        }
    }

    private static int[] intersect(int[] a, int[] b) {
        int[] out = new int[Math.min(a.length, b.length)];
        int n = 0;
        int i = 0;
        int j = 0;
        while (i < a.length && j < b.length) {
            if (a[i] < b[j]) i++;
            else if (a[i] > b[j]) j++;
            else { out[n++] = a[i]; i++; j++; }
        }
        return Arrays.copyOf(out, n);
    }

    private static int[][] invert(int[][] lists, int numFacts) {
        int[] c = new int[numFacts];
        for (int[] l : lists) for (int f : l) c[f]++;
        int[][] out = new int[numFacts][];
        for (int f = 0; f < numFacts; f++) out[f] = new int[c[f]];
        int[] fill = new int[numFacts];
        for (int o = 0; o < lists.length; o++) for (int f : lists[o]) out[f][fill[f]++] = o;
        return out;
    }

    /** Landmarks accepted after reaching {@code state} from a node with {@code parentAccepted} (null at the root). */
    long[] accept(long[] parentAccepted, int[] state) {
        long[] acc = parentAccepted == null ? new long[words] : parentAccepted.clone();
        for (int f : state) {
            int l = lmOfFact[f];
            if (l >= 0) acc[l >>> 6] |= 1L << l;
        }
        return acc;
    }

    /** Landmarks still to achieve: not accepted, or accepted but needed again. */
    int value(long[] acc, int[] state) {
        epoch++;
        for (int f : state) mark[f] = epoch;
        int h = 0;
        for (int l = 0; l < count; l++) {
            if ((acc[l >>> 6] & (1L << l)) == 0) {
                h++;
            } else if (mark[factOf[l]] != epoch) {
                if (goal[l]) {
                    h++;
                    continue;
                }
                for (int c : children[l]) {
                    if ((acc[c >>> 6] & (1L << c)) == 0) {
                        h++;
                        break;
                    }
                }
            }
        }
        return h;
    }
}
