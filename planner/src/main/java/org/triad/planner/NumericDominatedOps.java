package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

/**
 * {@link DominatedOps} for numeric tasks: instances a plan never needs, because a kept instance does
 * what they do to everything that matters, with the same numeric effects. The battery hospital's
 * {@code guide} of a person along a corridor drains the battery and costs as much as {@code move} along
 * it; when no goal and no kept action looks at where people are, every guided walk is a move, and
 * {@code startFollowing} and {@code walk} go with it; the search then no longer meets a state per place a
 * person could be walked to (the fixture delivery: 75 states expanded before, 15 after).
 * <p>
 * <b>Why it is safe.</b> As in {@link DominatedOps}, with R the facts kept instances' preconditions and
 * the goal need true (or look at under a disjunction or a comparison), N those they need false (or look
 * at so): an instance o is left out when it has no numeric effect and adds nothing in R and deletes
 * nothing in N, or when a kept d has a precondition whose top-level conjuncts are among o's, adds and
 * deletes no more than o, has exactly o's numeric effects, and o's further adds miss R and its further
 * deletes miss N. Replacing o by d in a plan (dropping a useless o) keeps the fluents' values step by
 * step (the same numeric effects, whose values depend on fluents only), R's facts true where they were
 * and N's false where they were: the plan stays valid, with the same metric, and no longer. Only for
 * tasks without conditional effects; an instance whose precondition nests conjunctions or disjunctions
 * is always kept; a fixpoint from "everything else left out", in instance order (deterministic).
 */
final class NumericDominatedOps {
    private static final int MAX_OPS = 20_000;
    private static final int MAX_CANDIDATES = 64;

    /** The number of the empty multiset of numeric effects. */
    private static final int NO_NUMERIC = -1;

    private NumericDominatedOps() { }

    /**
     * An instance flattened: top-level fact conjuncts, other conjuncts, merged effects; {@code numeric}
     * numbers the instance's multiset of numeric effects (equal numbers, equal effects), so comparing
     * two instances' effects is comparing two ints.
     */
    private record Shape(int[] preTrue, int[] preFalse, List<NumericTask.Cond> other, int[] adds, int[] dels, int numeric) { }

    /**
     * What the analysis reads of the instances alone, computed once per grounding and kept with it
     * ({@link NumericGroundingCache}): each instance's shape (null: nested, always kept) and the
     * instances adding each fact. {@link #NONE} when the analysis does not apply (too many instances,
     * conditional effects).
     */
    static final class Shapes {
        static final Shapes NONE = new Shapes(null, null);
        private final Shape[] shapes;
        private final int[][] addOf;

        private Shapes(Shape[] shapes, int[][] addOf) {
            this.shapes = shapes;
            this.addOf = addOf;
        }

        static Shapes of(NumericTask task) {
            int no = task.ops.size();
            if (no > MAX_OPS) return NONE;
            for (NumericTask.Op op : task.ops) for (NumericTask.Effects e : op.effects()) if (e.when() != NumericTask.TRUE) return NONE;
            Shape[] shapes = new Shape[no];
            Map<Map<NumericTask.NumEffect, Integer>, Integer> numbering = new HashMap<>();
            for (int o = 0; o < no; o++) shapes[o] = shape(task.ops.get(o), numbering);
            int nf = task.factNames.size();
            int[] count = new int[nf];
            for (Shape s : shapes) if (s != null) for (int a : s.adds) count[a]++;
            int[][] addOf = new int[nf][];
            for (int f = 0; f < nf; f++) addOf[f] = new int[count[f]];
            Arrays.fill(count, 0);
            for (int o = 0; o < no; o++) if (shapes[o] != null) for (int a : shapes[o].adds) addOf[a][count[a]++] = o;
            return new Shapes(shapes, addOf);
        }
    }

    /** Per instance, whether the search may leave it out; null when none is or the analysis does not apply. */
    static boolean[] of(NumericTask task) {
        Shapes sh = task.opShapes != null ? task.opShapes : Shapes.of(task);
        if (sh.shapes == null) return null;
        Shape[] shapes = sh.shapes;
        int[][] addOf = sh.addOf;
        int no = shapes.length;
        int nf = task.factNames.size();
        int[] needTrue = new int[nf];
        int[] needFalse = new int[nf];
        need(task.goal, true, needTrue, needFalse);
        boolean[] out = new boolean[no];
        Arrays.fill(out, true);
        for (int o = 0; o < no; o++) {
            if (shapes[o] != null) continue;
            out[o] = false;
            need(task.ops.get(o).pre(), true, needTrue, needFalse);
        }
        boolean changed = true;
        while (changed) {
            changed = false;
            for (int o = 0; o < no; o++) {
                if (!out[o] || useless(shapes[o], needTrue, needFalse)) continue;
                int d = dominator(shapes, o, addOf, out, needTrue, needFalse);
                int keep = d >= 0 ? d : o;
                if (!out[keep]) continue;
                out[keep] = false;
                need(task.ops.get(keep).pre(), true, needTrue, needFalse);
                changed = true;
            }
        }
        for (boolean b : out) if (b) return out;
        return null;
    }

    /** Counts the facts a condition looks at: a top-level positive one as needed true, negative false, any other both. */
    private static void need(NumericTask.Cond c, boolean top, int[] needTrue, int[] needFalse) {
        if (c instanceof NumericTask.Fact f) {
            if (!top || f.positive()) needTrue[f.id()]++;
            if (!top || !f.positive()) needFalse[f.id()]++;
        } else if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) need(p, top, needTrue, needFalse);
        } else if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) need(p, false, needTrue, needFalse);
        }
        // comparisons read fluents only; constants nothing
    }

    private static Shape shape(NumericTask.Op op, Map<Map<NumericTask.NumEffect, Integer>, Integer> numbering) {
        TreeSet<Integer> preTrue = new TreeSet<>();
        TreeSet<Integer> preFalse = new TreeSet<>();
        List<NumericTask.Cond> other = new ArrayList<>();
        List<NumericTask.Cond> conjuncts = op.pre() instanceof NumericTask.All a ? a.parts() : List.of(op.pre());
        for (NumericTask.Cond c : conjuncts) {
            if (c instanceof NumericTask.Fact f) (f.positive() ? preTrue : preFalse).add(f.id());
            else if (c instanceof NumericTask.All || c instanceof NumericTask.Any) return null; // nested: not compared
            else if (c != NumericTask.TRUE) other.add(c);
        }
        TreeSet<Integer> adds = new TreeSet<>();
        TreeSet<Integer> dels = new TreeSet<>();
        Map<NumericTask.NumEffect, Integer> numeric = new HashMap<>();
        for (NumericTask.Effects e : op.effects()) {
            for (int a : e.adds()) adds.add(a);
            for (int d : e.dels()) dels.add(d);
            for (NumericTask.NumEffect n : e.numeric()) numeric.merge(n, 1, Integer::sum);
        }
        int id = numeric.isEmpty() ? NO_NUMERIC : numbering.computeIfAbsent(numeric, k -> numbering.size());
        return new Shape(ints(preTrue), ints(preFalse), other, ints(adds), ints(dels), id);
    }

    private static int[] ints(TreeSet<Integer> s) {
        return s.stream().mapToInt(Integer::intValue).toArray();
    }

    private static boolean useless(Shape s, int[] needTrue, int[] needFalse) {
        if (s.numeric != NO_NUMERIC) return false;
        for (int a : s.adds) if (needTrue[a] > 0) return false;
        for (int d : s.dels) if (needFalse[d] > 0) return false;
        return true;
    }

    private static int dominator(Shape[] shapes, int o, int[][] addOf, boolean[] out, int[] needTrue, int[] needFalse) {
        int examined = 0;
        int first = -1;
        for (int a : shapes[o].adds) {
            for (int d : addOf[a]) {
                if (d == o) continue;
                if (++examined > MAX_CANDIDATES) return first;
                if (!dominates(shapes[d], shapes[o], needTrue, needFalse)) continue;
                if (!out[d]) return d;
                if (first < 0) first = d;
            }
        }
        return first;
    }

    private static boolean dominates(Shape d, Shape o, int[] needTrue, int[] needFalse) {
        if (d.numeric != o.numeric) return false;
        if (!DominatedOps.subset(d.preTrue, o.preTrue) || !DominatedOps.subset(d.preFalse, o.preFalse) || !DominatedOps.subset(d.adds, o.adds)
                || !DominatedOps.subset(d.dels, o.dels)) return false;
        if (!o.other.containsAll(d.other)) return false;
        for (int a : o.adds) if (needTrue[a] > 0 && Arrays.binarySearch(d.adds, a) < 0) return false;
        for (int x : o.dels) if (needFalse[x] > 0 && Arrays.binarySearch(d.dels, x) < 0) return false;
        return true;
    }
}
