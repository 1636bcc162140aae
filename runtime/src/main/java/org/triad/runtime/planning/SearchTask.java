package org.triad.runtime.planning;

import java.util.ArrayList;
import java.util.List;

/**
 * The search-time view of a grounded problem: operators as int arrays over fact ids, with the
 * indexes heuristics and successor generation need. States are sorted int arrays of true facts.
 */
final class SearchTask {
    final int numFacts;
    final GroundOp[] ops;
    final int[][] pre;
    final int[][] neg;
    final int[][] add;
    final int[][] del;
    /** Operators having the fact as a positive precondition. */
    final int[][] preOf;
    /** Operators triggered for applicability tests by their first precondition. */
    final int[][] firstPreOf;
    final int[] noPre;
    final Grounder grounder;

    SearchTask(Grounder grounder, List<GroundOp> opList, int numFacts) {
        this.grounder = grounder;
        this.numFacts = numFacts;
        ops = opList.toArray(new GroundOp[0]);
        int n = ops.length;
        pre = new int[n][];
        neg = new int[n][];
        add = new int[n][];
        del = new int[n][];
        int[] preCount = new int[numFacts];
        int[] firstCount = new int[numFacts];
        List<Integer> none = new ArrayList<>();
        for (int o = 0; o < n; o++) {
            pre[o] = ops[o].pre();
            neg[o] = ops[o].neg();
            add[o] = ops[o].add();
            del[o] = ops[o].del();
            for (int f : pre[o]) preCount[f]++;
            if (pre[o].length == 0) none.add(o); else firstCount[pre[o][0]]++;
        }
        preOf = new int[numFacts][];
        firstPreOf = new int[numFacts][];
        for (int f = 0; f < numFacts; f++) {
            preOf[f] = new int[preCount[f]];
            firstPreOf[f] = new int[firstCount[f]];
        }
        int[] fill = new int[numFacts];
        int[] fill2 = new int[numFacts];
        for (int o = 0; o < n; o++) {
            for (int f : pre[o]) preOf[f][fill[f]++] = o;
            if (pre[o].length > 0) firstPreOf[pre[o][0]][fill2[pre[o][0]]++] = o;
        }
        noPre = none.stream().mapToInt(Integer::intValue).toArray();
    }
}
