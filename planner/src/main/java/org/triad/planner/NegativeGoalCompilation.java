package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A task whose negative goals are positive ones: every fact that must be false in a goal or a
 * precondition gets a complement fact {@code numFacts + k}, true exactly when the fact is false
 * (in the initial state, added by the fact's deleters, deleted by its adders). The heuristics ignore
 * negative goals and preconditions, so on a task whose goals are all negative (every gate of a
 * circuit done, i.e. its "required" fact deleted) they are blind; on the compiled task they count
 * what making those facts false costs. The operators are the same, in the same order, so a plan of
 * the compiled task is a plan of the original one (states differ only by the complement facts).
 */
final class NegativeGoalCompilation {
    final SearchTask task;
    final int[] init;
    final int[] goalPos;

    private NegativeGoalCompilation(SearchTask task, int[] init, int[] goalPos) {
        this.task = task;
        this.init = init;
        this.goalPos = goalPos;
    }

    /**
     * The compiled task, or null when there is no negative goal (nothing to gain) or an operator is
     * more than preconditions, adds and deletes (a record with further components, e.g. conditional
     * effects, is not equal to its plain copy): the compilation only knows plain operators.
     */
    static NegativeGoalCompilation of(SearchTask t, int[] init, int[] goalPos, int[] goalNeg) {
        if (goalNeg.length == 0) return null;
        for (GroundOp op : t.ops) {
            if (!op.equals(new GroundOp(op.name(), op.args(), op.pre(), op.neg(), op.add(), op.del(), op.cost()))) return null;
        }
        int[] complement = new int[t.numFacts];
        Arrays.fill(complement, -1);
        int k = 0;
        for (int f : goalNeg) if (complement[f] < 0) complement[f] = t.numFacts + k++;
        for (int[] ns : t.neg) for (int f : ns) if (complement[f] < 0) complement[f] = t.numFacts + k++;
        List<GroundOp> ops = new ArrayList<>(t.ops.length);
        for (int o = 0; o < t.ops.length; o++) {
            GroundOp op = t.ops[o];
            int[] add = t.add[o];
            int[] del = t.del[o];
            List<Integer> pre = boxed(t.pre[o]);
            List<Integer> neg = new ArrayList<>();
            for (int f : t.neg[o]) {
                if (complement[f] >= 0) pre.add(complement[f]); else neg.add(f);
            }
            List<Integer> add2 = boxed(add);
            List<Integer> del2 = boxed(del);
            for (int f : del) if (complement[f] >= 0 && Arrays.binarySearch(add, f) < 0) add2.add(complement[f]);
            for (int f : add) if (complement[f] >= 0) del2.add(complement[f]);
            ops.add(new GroundOp(op.name(), op.args(), Grounder.sortedUnique(pre), Grounder.sortedUnique(neg),
                    Grounder.sortedUnique(add2), Grounder.sortedUnique(del2), op.cost()));
        }
        List<Integer> init2 = boxed(init);
        for (int f = 0; f < t.numFacts; f++) if (complement[f] >= 0 && Arrays.binarySearch(init, f) < 0) init2.add(complement[f]);
        List<Integer> goal2 = boxed(goalPos);
        for (int f : goalNeg) goal2.add(complement[f]);
        SearchTask compiled = new SearchTask(t.grounder, ops, t.numFacts + k);
        return new NegativeGoalCompilation(compiled, Grounder.sortedUnique(init2), Grounder.sortedUnique(goal2));
    }

    private static List<Integer> boxed(int[] xs) {
        List<Integer> out = new ArrayList<>(xs.length + 4);
        for (int x : xs) out.add(x);
        return out;
    }
}
