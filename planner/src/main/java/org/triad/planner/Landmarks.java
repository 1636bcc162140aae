package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Fact landmarks found by back-chaining from the goals: a precondition shared by every achiever of
 * a landmark that can be applied before it (in the relaxed task without the landmark's achievers)
 * is itself a landmark, ordered greedy-necessarily before it. Where the achievers share no fact but
 * each needs a fact of one predicate (a ball in the left or the right gripper, a passenger in one of
 * a few lifts), the set of those facts is a disjunctive landmark (at most
 * {@link #MAX_DISJUNCTION} facts, none true initially nor a simple landmark), as in the RHW
 * landmarks LAMA uses: without them the landmark count sees no progress in picking up a second ball
 * before a trip, so the plan carries one at a time. The landmark-count heuristic (as in LAMA) counts
 * landmarks not yet accepted on the path plus accepted ones required again; a disjunctive landmark
 * is accepted, and true, when any of its facts is.
 */
final class Landmarks {
    /** Largest disjunctive landmark (Fast Downward's RHW uses 4 as well). */
    static final int MAX_DISJUNCTION = 4;

    final int count;
    /** The facts of each landmark (one for a simple landmark), sorted. */
    private final int[][] factsOf;
    /** For each fact: the landmarks it belongs to (null for none). */
    private final int[][] lmsOfFact;
    private final boolean[] goal;
    /** For landmark l: the landmarks that must be true right before l is first achieved ... and after. */
    private final int[][] children;
    private final int words;
    private final int[] mark;
    private int epoch;

    Landmarks(SearchTask task, int[] init, int[] goalPos, long deadline) {
        this(task, init, goalPos, deadline, true);
    }

    /** @param disjunctive whether to look for disjunctive landmarks too (each costs a relaxed exploration) */
    Landmarks(SearchTask task, int[] init, int[] goalPos, long deadline, boolean disjunctive) {
        // over the relaxed operators: a conditional achiever needs its condition too
        RelaxedOps t = task.relaxed;
        int nf = t.size;
        int[] relaxedInit = t.initial(init);
        int[][] addOf = invert(t.add, nf);
        int[] simpleOf = new int[nf];
        Arrays.fill(simpleOf, -1);
        List<int[]> nodes = new ArrayList<>();
        List<List<Integer>> kids = new ArrayList<>();
        Map<IntKey, Integer> disjunctions = new HashMap<>();
        boolean[] inInit = new boolean[nf];
        for (int f : init) inInit[f] = true;
        for (int g : goalPos) addSimple(g, simpleOf, nodes, kids);
        boolean[] reach = new boolean[nf];
        int[] unsat = new int[t.count];
        int[] fifo = new int[nf];
        boolean[] excluded = new boolean[t.count];
        // the predicate of each fact, to group achievers' preconditions into disjunctions
        int[] predicate = new int[nf];
        Arrays.fill(predicate, -1);
        for (int f = 0; f < task.numFacts && task.grounder != null; f++) {
            if (f < task.grounder.facts.size()) predicate[f] = task.grounder.facts.get(f)[0];
        }
        for (int qi = 0; qi < nodes.size() && System.nanoTime() < deadline; qi++) {
            int[] lm = nodes.get(qi);
            boolean trueInitially = false;
            for (int f : lm) trueInitially |= inInit[f];
            if (trueInitially) continue;
            Arrays.fill(excluded, false);
            for (int f : lm) for (int o : addOf[f]) excluded[o] = true;
            relaxedReach(t, relaxedInit, excluded, reach, unsat, fifo);
            int[] shared = null;
            List<int[]> firstAchievers = new ArrayList<>();
            for (int f : lm) {
                for (int o : addOf[f]) {
                    boolean possible = true;
                    for (int p : t.pre[o]) if (!reach[p]) { possible = false; break; }
                    if (!possible) continue;
                    firstAchievers.add(t.pre[o]);
                    shared = shared == null ? t.pre[o].clone() : intersect(shared, t.pre[o]);
                }
            }
            if (shared == null) continue;
            for (int p : shared) {
                if (p >= task.numFacts) continue; // a complement: never in a state, so never accepted
                int lp = addSimple(p, simpleOf, nodes, kids);
                if (!kids.get(lp).contains(qi)) kids.get(lp).add(qi);
            }
            if (!disjunctive) continue;
            // disjunctions: per predicate, one precondition fact from every first achiever
            Map<Integer, int[]> byPredicate = new java.util.TreeMap<>();
            boolean first = true;
            for (int[] pre : firstAchievers) {
                Map<Integer, int[]> here = new java.util.TreeMap<>();
                for (int p : pre) {
                    if (p >= task.numFacts || predicate[p] < 0 || Arrays.binarySearch(shared, p) >= 0) continue;
                    here.merge(predicate[p], new int[] {p}, Grounder::union);
                }
                if (first) {
                    byPredicate.putAll(here);
                    first = false;
                } else {
                    byPredicate.keySet().retainAll(here.keySet());
                    for (Map.Entry<Integer, int[]> e : byPredicate.entrySet()) e.setValue(Grounder.union(e.getValue(), here.get(e.getKey())));
                }
            }
            for (int[] set : byPredicate.values()) {
                if (set.length < 2 || set.length > MAX_DISJUNCTION) continue;
                boolean usable = true;
                for (int f : set) usable &= !inInit[f];
                if (!usable) continue;
                IntKey key = new IntKey(set);
                Integer lp = disjunctions.get(key);
                if (lp == null) {
                    lp = nodes.size();
                    disjunctions.put(key, lp);
                    nodes.add(set);
                    kids.add(new ArrayList<>());
                }
                if (!kids.get(lp).contains(qi)) kids.get(lp).add(qi);
            }
        }
        // a disjunction holding a simple landmark says nothing more than it (and would count twice)
        int[] newId = new int[nodes.size()];
        int kept = 0;
        for (int l = 0; l < nodes.size(); l++) {
            int[] lm = nodes.get(l);
            boolean drop = false;
            if (lm.length > 1) for (int f : lm) drop |= simpleOf[f] >= 0;
            newId[l] = drop ? -1 : kept++;
        }
        count = kept;
        factsOf = new int[count][];
        children = new int[count][];
        int[] memberships = new int[nf];
        for (int l = 0; l < nodes.size(); l++) {
            if (newId[l] < 0) continue;
            factsOf[newId[l]] = nodes.get(l);
            children[newId[l]] = kids.get(l).stream().mapToInt(Integer::intValue).filter(c -> newId[c] >= 0).map(c -> newId[c]).toArray();
            for (int f : nodes.get(l)) memberships[f]++;
        }
        lmsOfFact = new int[nf][];
        for (int l = 0; l < count; l++) {
            for (int f : factsOf[l]) {
                if (lmsOfFact[f] == null) lmsOfFact[f] = new int[memberships[f]];
                lmsOfFact[f][lmsOfFact[f].length - memberships[f]--] = l;
            }
        }
        goal = new boolean[count];
        for (int g : goalPos) goal[newId[simpleOf[g]]] = true;
        words = (count + 63) >>> 6;
        mark = new int[nf];
    }

    private static int addSimple(int fact, int[] simpleOf, List<int[]> nodes, List<List<Integer>> kids) {
        if (simpleOf[fact] >= 0) return simpleOf[fact];
        simpleOf[fact] = nodes.size();
        nodes.add(new int[] {fact});
        kids.add(new ArrayList<>());
        return nodes.size() - 1;
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
            int[] ls = lmsOfFact[f];
            if (ls == null) continue;
            for (int l : ls) acc[l >>> 6] |= 1L << l;
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
            } else if (!holds(l)) {
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

    private boolean holds(int l) {
        for (int f : factsOf[l]) if (mark[f] == epoch) return true;
        return false;
    }
}
