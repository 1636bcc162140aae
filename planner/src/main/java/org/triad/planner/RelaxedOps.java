package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The operators as the delete relaxation sees them. With conditional effects, each operator splits
 * into its unconditional part and one relaxed operator per conditional effect, whose precondition
 * is the operator's plus the effect's condition (as Fast Downward's unary operators do); {@code op}
 * maps each back to its operator. A fact needed false somewhere (a negative precondition or
 * condition) gets a complement fact {@code numFacts + k}: true in a state that lacks the fact, made
 * by the operators that delete it, and required where the fact must be false (FF's compilation of
 * negations), so the heuristic sees what making a fact false costs. Without conditional effects and
 * negative preconditions this is the task itself (the same arrays), so STRIPS tasks pay nothing.
 */
final class RelaxedOps {
    final int count;
    final int[][] pre;
    final int[][] add;
    /** The operator each relaxed operator belongs to. */
    final int[] op;
    final int[][] preOf;
    final int[] noPre;
    /** Facts plus complements. */
    final int size;
    /** The facts that have a complement; the complement of {@code negFacts[k]} is {@code numFacts + k}. */
    final int[] negFacts;
    final int numFacts;

    RelaxedOps(SearchTask t) {
        numFacts = t.numFacts;
        int[] complement = new int[t.numFacts];
        Arrays.fill(complement, -1);
        List<Integer> negList = new ArrayList<>();
        // a derived fact gets no complement: nothing deletes it, rules just stop deriving it, so a
        // relaxation must not require it false (dropping that condition keeps the relaxation sound)
        boolean[] derived = t.axioms == null ? new boolean[t.numFacts] : t.axioms.derivedFact;
        for (int o = 0; o < t.ops.length; o++) {
            for (int f : t.neg[o]) if (complement[f] < 0 && !derived[f]) { complement[f] = t.numFacts + negList.size(); negList.add(f); }
            if (t.when[o] == null) continue;
            for (GroundOp.When w : t.when[o]) {
                for (int f : w.neg()) if (complement[f] < 0 && !derived[f]) { complement[f] = t.numFacts + negList.size(); negList.add(f); }
            }
        }
        if (t.axioms != null) {
            for (int[] ns : t.axioms.neg) {
                for (int f : ns) if (complement[f] < 0 && !derived[f]) { complement[f] = t.numFacts + negList.size(); negList.add(f); }
            }
        }
        negFacts = negList.stream().mapToInt(Integer::intValue).toArray();
        size = t.numFacts + negFacts.length;
        if (!t.hasConditionalEffects && negFacts.length == 0 && t.axioms == null) {
            count = t.ops.length;
            pre = t.pre;
            add = t.add;
            op = new int[count];
            for (int o = 0; o < count; o++) op[o] = o;
            preOf = t.preOf;
            noPre = t.noPre;
            return;
        }
        List<int[]> p = new ArrayList<>();
        List<int[]> a = new ArrayList<>();
        List<Integer> owner = new ArrayList<>();
        for (int o = 0; o < t.ops.length; o++) {
            int[] base = Grounder.union(t.pre[o], complements(t.neg[o], complement));
            int[] baseAdd = Grounder.union(t.add[o], complements(t.del[o], complement));
            if (baseAdd.length > 0 || t.when[o] == null) {
                p.add(base);
                a.add(baseAdd);
                owner.add(o);
            }
            if (t.when[o] == null) continue;
            for (GroundOp.When w : t.when[o]) {
                int[] wAdd = Grounder.union(w.add(), complements(w.del(), complement));
                if (wAdd.length == 0) continue;
                p.add(Grounder.union(base, Grounder.union(w.pre(), complements(w.neg(), complement))));
                a.add(wAdd);
                owner.add(o);
            }
        }
        if (t.axioms != null) {
            // rules relax like operators that belong to no action (op -1: not counted, never helpful)
            for (int r = 0; r < t.axioms.head.length; r++) {
                p.add(Grounder.union(t.axioms.pre[r], complements(t.axioms.neg[r], complement)));
                a.add(new int[] {t.axioms.head[r]});
                owner.add(-1);
            }
        }
        count = p.size();
        pre = p.toArray(new int[0][]);
        add = a.toArray(new int[0][]);
        op = owner.stream().mapToInt(Integer::intValue).toArray();
        int[] c = new int[size];
        List<Integer> none = new ArrayList<>();
        for (int r = 0; r < count; r++) {
            for (int f : pre[r]) c[f]++;
            if (pre[r].length == 0) none.add(r);
        }
        preOf = new int[size][];
        for (int f = 0; f < size; f++) preOf[f] = new int[c[f]];
        int[] fill = new int[size];
        for (int r = 0; r < count; r++) for (int f : pre[r]) preOf[f][fill[f]++] = r;
        noPre = none.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The complements of those facts that have one, sorted. */
    private static int[] complements(int[] facts, int[] complement) {
        int n = 0;
        int[] out = new int[facts.length];
        for (int f : facts) if (complement[f] >= 0) out[n++] = complement[f];
        return Grounder.sortedUnique(Arrays.copyOf(out, n));
    }

    /** The relaxed initial facts of a state: its facts and the complements of the facts it lacks. */
    int[] initial(int[] state) {
        if (negFacts.length == 0) return state;
        int[] out = Arrays.copyOf(state, state.length + negFacts.length);
        int n = state.length;
        for (int k = 0; k < negFacts.length; k++) {
            if (Arrays.binarySearch(state, negFacts[k]) < 0) out[n++] = numFacts + k;
        }
        return Arrays.copyOf(out, n);
    }
}
