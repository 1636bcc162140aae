package org.triad.planner;

import java.util.ArrayList;
import java.util.List;

/**
 * The operators as the delete relaxation sees them: with conditional effects, each operator splits
 * into its unconditional part and one relaxed operator per conditional effect, whose precondition
 * is the operator's plus the effect's condition (as Fast Downward's unary operators do); {@code op}
 * maps each back to its operator. Without conditional effects this is the task itself (the same
 * arrays), so STRIPS tasks pay nothing.
 */
final class RelaxedOps {
    final int count;
    final int[][] pre;
    final int[][] add;
    /** The operator each relaxed operator belongs to. */
    final int[] op;
    final int[][] preOf;
    final int[] noPre;

    RelaxedOps(SearchTask t) {
        if (!t.hasConditionalEffects) {
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
            if (t.add[o].length > 0 || t.when[o] == null) {
                p.add(t.pre[o]);
                a.add(t.add[o]);
                owner.add(o);
            }
            if (t.when[o] == null) continue;
            for (GroundOp.When w : t.when[o]) {
                if (w.add().length == 0) continue;
                p.add(Grounder.union(t.pre[o], w.pre()));
                a.add(w.add());
                owner.add(o);
            }
        }
        count = p.size();
        pre = p.toArray(new int[0][]);
        add = a.toArray(new int[0][]);
        op = owner.stream().mapToInt(Integer::intValue).toArray();
        int[] c = new int[t.numFacts];
        List<Integer> none = new ArrayList<>();
        for (int r = 0; r < count; r++) {
            for (int f : pre[r]) c[f]++;
            if (pre[r].length == 0) none.add(r);
        }
        preOf = new int[t.numFacts][];
        for (int f = 0; f < t.numFacts; f++) preOf[f] = new int[c[f]];
        int[] fill = new int[t.numFacts];
        for (int r = 0; r < count; r++) for (int f : pre[r]) preOf[f][fill[f]++] = r;
        noPre = none.stream().mapToInt(Integer::intValue).toArray();
    }
}
