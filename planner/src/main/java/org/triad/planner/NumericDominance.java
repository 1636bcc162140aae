package org.triad.planner;

/**
 * Fluents whose more (or less) is never worse: a battery that every condition only needs to be at
 * least something, a load that every condition needs to be at most something. When such a fluent is
 * read by no effect's value, no effect condition and not by the metric, and changed only by
 * {@code increase}, {@code decrease}, {@code assign} and scaling by a positive constant, then of two
 * states with the same facts and other values, the one with more battery (less load) and a metric no
 * larger can do all the other can, at no more cost: the other is dominated and need not be searched.
 * This is what makes a robot's route with a battery a search over places rather than over places
 * times charge levels. A fluent read by nothing at all ({@link #IRRELEVANT}) is left out of the
 * comparison altogether.
 */
final class NumericDominance {
    static final int NEITHER = 0;
    static final int MORE_IS_BETTER = 1;
    static final int LESS_IS_BETTER = -1;
    static final int IRRELEVANT = 2;

    /** Per fluent: {@link #MORE_IS_BETTER}, {@link #LESS_IS_BETTER}, {@link #IRRELEVANT} or {@link #NEITHER} (accumulators: NEITHER, they are the metric). */
    final int[] direction;
    /** Accumulators and every fluent with a direction: what a state's "rest" (facts and the other values) leaves out. */
    final boolean[] outsideRest;
    /** Whether some fluent has a direction (else dominance is equality and not worth checking). */
    final boolean any;
    /**
     * Whether every fluent a condition reads has a direction: the numbers are resources only (a battery,
     * a load), so the facts tell most of the way and a search guided by the facts alone is apt.
     */
    final boolean resourcesOnly;

    private NumericDominance(int[] direction, boolean[] outsideRest, boolean any, boolean resourcesOnly) {
        this.direction = direction;
        this.outsideRest = outsideRest;
        this.any = any;
        this.resourcesOnly = resourcesOnly;
    }

    static NumericDominance of(NumericTask task) {
        int nv = task.fluentNames.size();
        boolean[] up = new boolean[nv];
        boolean[] down = new boolean[nv];
        boolean[] excluded = new boolean[nv];
        conditions(task.goal, up, down);
        for (NumericTask.Op op : task.ops) {
            int refilled = refilled(task, op);
            for (NumericTask.Cond c : op.pre() instanceof NumericTask.All a ? a.parts() : java.util.List.of(op.pre())) {
                if (refilled < 0 || !isRefillGuard(c, refilled, refillValue(op, refilled))) conditions(c, up, down);
            }
            for (NumericTask.Effects e : op.effects()) {
                // a conditional effect that more charge could trigger may delete facts: no order there
                readsOf(e.when(), excluded);
                for (NumericTask.NumEffect n : e.numeric()) {
                    reads(n.value(), excluded);
                    boolean positiveFactor = n.value() instanceof NumericTask.Num k && k.value() > 0;
                    if (n.kind().startsWith("scale") && !positiveFactor) excluded[n.fluent()] = true;
                }
            }
        }
        if (task.metric != null) reads(task.metric, excluded);
        int[] direction = new int[nv];
        boolean[] outside = new boolean[nv];
        boolean any = false;
        for (int i = 0; i < nv; i++) {
            outside[i] = task.accumulator[i];
            if (task.accumulator[i] || excluded[i]) continue;
            direction[i] = up[i] && down[i] ? NEITHER : up[i] ? MORE_IS_BETTER : down[i] ? LESS_IS_BETTER : IRRELEVANT;
            if (direction[i] != NEITHER) {
                outside[i] = true;
                any = true;
            }
        }
        boolean resourcesOnly = true;
        for (int i = 0; i < nv; i++) if ((up[i] || down[i]) && (direction[i] == NEITHER || task.accumulator[i])) resourcesOnly = false;
        return new NumericDominance(direction, outside, any, resourcesOnly);
    }

    /**
     * The fluent an operator only refills, -1 if none: its one effect outside the accumulators is {@code
     * assign} of a constant, and the accumulators it changes only make the metric grow. A recharge guarded
     * by {@code (< (battery) 60)} that assigns 60 gives a state with less charge nothing that one with
     * at least 60 lacks, so its guard does not make less charge better ({@link #isRefillGuard}).
     */
    private static int refilled(NumericTask task, NumericTask.Op op) {
        int fluent = -1;
        for (NumericTask.Effects e : op.effects()) {
            if (e.when() != NumericTask.TRUE || e.adds().length > 0 || e.dels().length > 0) return -1;
            for (NumericTask.NumEffect n : e.numeric()) {
                if (task.accumulator[n.fluent()]) {
                    double w = task.metricWeight[n.fluent()];
                    if (!(n.value() instanceof NumericTask.Num k) || w * (n.kind().equals("decrease") ? -k.value() : k.value()) < 0) return -1;
                } else if (fluent >= 0 || !n.kind().equals("assign") || !(n.value() instanceof NumericTask.Num)) {
                    return -1;
                } else {
                    fluent = n.fluent();
                }
            }
        }
        return fluent;
    }

    private static double refillValue(NumericTask.Op op, int fluent) {
        for (NumericTask.Effects e : op.effects()) {
            for (NumericTask.NumEffect n : e.numeric()) if (n.fluent() == fluent) return ((NumericTask.Num) n.value()).value();
        }
        return Double.NaN;
    }

    /** Whether {@code c} is {@code fluent < t} or {@code fluent <= t} (either way round) with the refill's value at most {@code t}. */
    private static boolean isRefillGuard(NumericTask.Cond c, int fluent, double value) {
        if (!(c instanceof NumericTask.Cmp m)) return false;
        if (m.left() instanceof NumericTask.Var v && v.fluent() == fluent && m.right() instanceof NumericTask.Num t) {
            return (m.op().equals("<") || m.op().equals("<=")) && value <= t.value();
        }
        if (m.right() instanceof NumericTask.Var v && v.fluent() == fluent && m.left() instanceof NumericTask.Num t) {
            return (m.op().equals(">") || m.op().equals(">=")) && value <= t.value();
        }
        return false;
    }

    /** Whether {@code better}'s values are at least as good as {@code worse}'s in every directed fluent (equal rests assumed). */
    boolean covers(double[] better, double[] worse) {
        for (int i = 0; i < direction.length; i++) {
            int d = direction[i];
            if (d == NEITHER || d == IRRELEVANT) continue;
            double b = better[i];
            double w = worse[i];
            if (Double.isNaN(b) || Double.isNaN(w)) {
                if (Double.isNaN(b) != Double.isNaN(w)) return false;
            } else if (d == MORE_IS_BETTER ? b < w : b > w) {
                return false;
            }
        }
        return true;
    }

    /** Marks which way each fluent helps a condition: {@code up} a larger value can make it true, {@code down} a smaller one. */
    private static void conditions(NumericTask.Cond c, boolean[] up, boolean[] down) {
        if (c instanceof NumericTask.All a) a.parts().forEach(p -> conditions(p, up, down));
        else if (c instanceof NumericTask.Any a) a.parts().forEach(p -> conditions(p, up, down));
        else if (c instanceof NumericTask.Cmp m) {
            int dir = switch (m.op()) {
                case ">", ">=" -> 1;
                case "<", "<=" -> -1;
                default -> 0;
            };
            sign(m.left(), dir, up, down);
            sign(m.right(), -dir, up, down);
        }
    }

    /** For each fluent of {@code e}: which way helps when {@code e} should grow (1), fall (-1) or either (0); outside linear arithmetic, both. */
    private static void sign(NumericTask.Expr e, int dir, boolean[] up, boolean[] down) {
        if (e instanceof NumericTask.Var v) {
            if (dir >= 0) up[v.fluent()] = true;
            if (dir <= 0) down[v.fluent()] = true;
        } else if (e instanceof NumericTask.Neg n) {
            sign(n.operand(), -dir, up, down);
        } else if (e instanceof NumericTask.Bin b) {
            switch (b.op()) {
                case '+' -> {
                    sign(b.left(), dir, up, down);
                    sign(b.right(), dir, up, down);
                }
                case '-' -> {
                    sign(b.left(), dir, up, down);
                    sign(b.right(), -dir, up, down);
                }
                case '*' -> {
                    if (b.left() instanceof NumericTask.Num k) sign(b.right(), k.value() > 0 ? dir : k.value() < 0 ? -dir : 0, up, down);
                    else if (b.right() instanceof NumericTask.Num k) sign(b.left(), k.value() > 0 ? dir : k.value() < 0 ? -dir : 0, up, down);
                    else {
                        sign(b.left(), 0, up, down);
                        sign(b.right(), 0, up, down);
                    }
                }
                default -> {
                    if (b.right() instanceof NumericTask.Num k && k.value() != 0) sign(b.left(), k.value() > 0 ? dir : -dir, up, down);
                    else {
                        sign(b.left(), 0, up, down);
                        sign(b.right(), 0, up, down);
                    }
                }
            }
        }
    }

    private static void readsOf(NumericTask.Cond c, boolean[] read) {
        if (c instanceof NumericTask.Cmp m) {
            reads(m.left(), read);
            reads(m.right(), read);
        } else if (c instanceof NumericTask.All a) a.parts().forEach(p -> readsOf(p, read));
        else if (c instanceof NumericTask.Any a) a.parts().forEach(p -> readsOf(p, read));
    }

    private static void reads(NumericTask.Expr e, boolean[] read) {
        if (e instanceof NumericTask.Var v) read[v.fluent()] = true;
        else if (e instanceof NumericTask.Neg x) reads(x.operand(), read);
        else if (e instanceof NumericTask.Bin b) {
            reads(b.left(), read);
            reads(b.right(), read);
        }
    }
}
