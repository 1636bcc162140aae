package org.triad.planner;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * Metric-FF's numeric relaxation as a distance estimate: a relaxed planning graph whose facts are never
 * deleted and whose fluents are intervals [lo, hi] that every applicable action widens by its numeric
 * effects, layer by layer (so a battery that a recharge raises by 10 reaches 100 from 40 in six layers).
 * The estimate is the sum over the goal's conjuncts of the first layer at which each can hold
 * (additive, like h_add over layers); {@link #DEAD_END} when the graph stops growing first.
 */
final class NumericHeuristic {
    static final int DEAD_END = Integer.MAX_VALUE;
    /** Layers after which a goal still out of reach counts as very far (growth may go on forever). */
    private static final int MAX_LAYERS = 2_000;

    private final NumericTask task;
    private final List<NumericTask.Cond> goals = new ArrayList<>();

    /** Per operator, how much it makes the metric grow (its unconditional accumulator effects, valued in the initial state; at least 0). */
    private final double[] opCost;
    /** The least positive {@link #opCost}: the price of a step a numeric condition still needs. */
    private final double cheapest;
    private final boolean metricOnlyGrows;

    NumericHeuristic(NumericTask task) {
        this.task = task;
        if (task.goal instanceof NumericTask.All a) goals.addAll(a.parts());
        else goals.add(task.goal);
        opCost = new double[task.ops.size()];
        boolean grows = task.metric != null;
        for (int f = 0; f < task.fluentNames.size() && grows; f++) {
            if (NumericTask.mentions(task.metric, f) && (!task.accumulator[f] || task.metricWeight[f] < 0)) grows = false;
        }
        double least = Double.POSITIVE_INFINITY;
        for (int o = 0; o < task.ops.size(); o++) {
            double c = 0;
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (NumericTask.NumEffect n : e.numeric()) {
                    double w = task.metricWeight[n.fluent()];
                    if (w == 0) continue;
                    double amount = NumericTask.value(n.value(), task.initValues);
                    double delta = w * (n.kind().equals("decrease") ? -amount : amount);
                    if (!(n.value() instanceof NumericTask.Num) || delta < 0) grows = false;
                    if (e.when() == NumericTask.TRUE && Double.isFinite(delta)) c += delta;
                }
            }
            opCost[o] = Math.max(0, c);
            if (opCost[o] > 0) least = Math.min(least, opCost[o]);
        }
        cheapest = least == Double.POSITIVE_INFINITY ? 0 : least;
        metricOnlyGrows = grows;
    }

    /** Whether no step can make the metric smaller (so a partial plan as costly as a found one can be pruned). */
    boolean metricOnlyGrows() {
        return metricOnlyGrows;
    }

    /**
     * A cost-sensitive estimate for the metric: h_add over the same layered numeric relaxation, each
     * operator costing its {@link #opCost} plus its fact preconditions' costs, and a numeric condition
     * not yet true in the state the {@link #cheapest} step per layer it needs. Without action costs in
     * the metric it is the layer estimate. Not admissible; it orders weighted A* by cost.
     */
    double estimateCost(BitSet facts, double[] values) {
        if (cheapest == 0) {
            int h = estimate(facts, values);
            return h == DEAD_END ? Double.POSITIVE_INFINITY : h;
        }
        int nf = task.factNames.size();
        double[] fcost = new double[nf];
        java.util.Arrays.fill(fcost, Double.POSITIVE_INFINITY);
        for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) fcost[f] = 0;
        int[] opLayer = new int[task.ops.size()];
        java.util.Arrays.fill(opLayer, -1);
        int[] goalLayer = new int[goals.size()];
        java.util.Arrays.fill(goalLayer, -1);
        BitSet reached = (BitSet) facts.clone();
        double[] lo = values.clone();
        double[] hi = values.clone();
        int open = goals.size();
        int allReachedAt = -1;
        for (int layer = 0; layer <= MAX_LAYERS; layer++) {
            for (int g = 0; g < goals.size(); g++) {
                if (goalLayer[g] < 0 && holds(goals.get(g), reached, lo, hi)) {
                    goalLayer[g] = layer;
                    open--;
                }
            }
            if (open == 0 && allReachedAt < 0) allReachedAt = layer;
            BitSet nextFacts = (BitSet) reached.clone();
            double[] nextLo = lo.clone();
            double[] nextHi = hi.clone();
            boolean costChanged = false;
            for (int o = 0; o < task.ops.size(); o++) {
                NumericTask.Op op = task.ops.get(o);
                if (!holds(op.pre(), reached, lo, hi)) continue;
                if (opLayer[o] < 0) opLayer[o] = layer;
                double c = opCost[o] + factCost(op.pre(), fcost) + (numericHolds(op.pre(), values) ? 0 : cheapest * Math.max(1, opLayer[o]));
                for (NumericTask.Effects e : op.effects()) {
                    if (!holds(e.when(), reached, lo, hi)) continue;
                    double ce = e.when() == NumericTask.TRUE ? c : c + factCost(e.when(), fcost);
                    for (int f : e.adds()) {
                        nextFacts.set(f);
                        if (ce < fcost[f]) {
                            fcost[f] = ce;
                            costChanged = true;
                        }
                    }
                    if (allReachedAt < 0) for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) widen(n, lo, hi, nextLo, nextHi);
                }
            }
            if (allReachedAt >= 0 && (!costChanged || layer > allReachedAt + 8)) {
                double sum = 0;
                for (int g = 0; g < goals.size(); g++) {
                    NumericTask.Cond c = goals.get(g);
                    sum += factCost(c, fcost) + (numericHolds(c, values) ? 0 : cheapest * Math.max(1, goalLayer[g]));
                }
                return sum;
            }
            boolean changed = costChanged || !nextFacts.equals(reached);
            for (int i = 0; i < lo.length && !changed; i++) changed = nextLo[i] != lo[i] || nextHi[i] != hi[i];
            if (!changed) return Double.POSITIVE_INFINITY;
            reached = nextFacts;
            lo = nextLo;
            hi = nextHi;
        }
        return Double.POSITIVE_INFINITY;
    }

    /** The summed cost of a condition's facts (the cheapest part of a disjunction). */
    private static double factCost(NumericTask.Cond c, double[] fcost) {
        if (c instanceof NumericTask.Fact f) return f.positive() ? fcost[f.id()] : 0;
        if (c instanceof NumericTask.All a) {
            double s = 0;
            for (NumericTask.Cond p : a.parts()) s += factCost(p, fcost);
            return s;
        }
        if (c instanceof NumericTask.Any a) {
            double m = Double.POSITIVE_INFINITY;
            for (NumericTask.Cond p : a.parts()) m = Math.min(m, factCost(p, fcost));
            return m == Double.POSITIVE_INFINITY ? 0 : m;
        }
        return 0;
    }

    /** Whether the condition's comparisons hold in the state's values (its facts not considered). */
    private static boolean numericHolds(NumericTask.Cond c, double[] values) {
        if (c instanceof NumericTask.Cmp m) {
            return NumericTask.holds(m.op(), NumericTask.value(m.left(), values), NumericTask.value(m.right(), values));
        }
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!numericHolds(p, values)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (numericHolds(p, values)) return true;
            return a.parts().isEmpty();
        }
        return true;
    }

    int estimate(BitSet facts, double[] values) {
        BitSet reached = (BitSet) facts.clone();
        double[] lo = values.clone();
        double[] hi = values.clone();
        boolean[] done = new boolean[goals.size()];
        int open = goals.size();
        int sum = 0;
        boolean checkedOptimistically = false;
        for (int layer = 0; layer <= MAX_LAYERS; layer++) {
            for (int g = 0; g < goals.size(); g++) {
                if (!done[g] && holds(goals.get(g), reached, lo, hi)) {
                    done[g] = true;
                    open--;
                    sum += layer;
                }
            }
            if (open == 0) return sum;
            BitSet nextFacts = (BitSet) reached.clone();
            double[] nextLo = lo.clone();
            double[] nextHi = hi.clone();
            for (NumericTask.Op op : task.ops) {
                if (!holds(op.pre(), reached, lo, hi)) continue;
                for (NumericTask.Effects e : op.effects()) {
                    if (!holds(e.when(), reached, lo, hi)) continue;
                    for (int f : e.adds()) nextFacts.set(f);
                    for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) widen(n, lo, hi, nextLo, nextHi);
                }
            }
            boolean factsChanged = !nextFacts.equals(reached);
            boolean changed = factsChanged;
            for (int i = 0; i < lo.length && !changed; i++) changed = nextLo[i] != lo[i] || nextHi[i] != hi[i];
            if (!changed) return DEAD_END;
            if (!factsChanged && !checkedOptimistically) {
                // only numbers still grow, perhaps forever: a goal that needs a fact no action can add is out of reach
                checkedOptimistically = true;
                if (!optimisticallyReachable(reached, done)) return DEAD_END;
            }
            reached = nextFacts;
            lo = nextLo;
            hi = nextHi;
        }
        return sum + open * MAX_LAYERS;
    }

    /** Whether every open goal can hold when facts are never deleted and every comparison counts as true. */
    private boolean optimisticallyReachable(BitSet from, boolean[] done) {
        BitSet facts = (BitSet) from.clone();
        boolean grew = true;
        while (grew) {
            grew = false;
            for (NumericTask.Op op : task.ops) {
                if (!optimistic(op.pre(), facts)) continue;
                for (NumericTask.Effects e : op.effects()) {
                    if (!optimistic(e.when(), facts)) continue;
                    for (int f : e.adds()) {
                        if (!facts.get(f)) {
                            facts.set(f);
                            grew = true;
                        }
                    }
                }
            }
        }
        for (int g = 0; g < goals.size(); g++) if (!done[g] && !optimistic(goals.get(g), facts)) return false;
        return true;
    }

    private static boolean optimistic(NumericTask.Cond c, BitSet facts) {
        if (c instanceof NumericTask.Fact f) return !f.positive() || facts.get(f.id());
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!optimistic(p, facts)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (optimistic(p, facts)) return true;
            return false;
        }
        return !(c instanceof NumericTask.Const k) || k.value();
    }

    private static void widen(NumericTask.NumEffect n, double[] lo, double[] hi, double[] nextLo, double[] nextHi) {
        int f = n.fluent();
        double[] v = interval(n.value(), lo, hi);
        if (v == null) return;
        double a;
        double b;
        if (n.kind().equals("assign")) {
            a = v[0];
            b = v[1];
        } else {
            if (Double.isNaN(lo[f])) return;
            double[] c = switch (n.kind()) {
                case "increase" -> new double[] { lo[f] + v[0], hi[f] + v[1] };
                case "decrease" -> new double[] { lo[f] - v[1], hi[f] - v[0] };
                case "scale-up" -> product(new double[] { lo[f], hi[f] }, v);
                default -> quotient(new double[] { lo[f], hi[f] }, v);
            };
            if (c == null) return;
            a = c[0];
            b = c[1];
        }
        nextLo[f] = Double.isNaN(nextLo[f]) ? a : Math.min(nextLo[f], a);
        nextHi[f] = Double.isNaN(nextHi[f]) ? b : Math.max(nextHi[f], b);
    }

    static boolean holds(NumericTask.Cond c, BitSet facts, double[] lo, double[] hi) {
        if (c instanceof NumericTask.Fact f) return !f.positive() || facts.get(f.id());
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!holds(p, facts, lo, hi)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (holds(p, facts, lo, hi)) return true;
            return false;
        }
        if (c instanceof NumericTask.Const k) return k.value();
        NumericTask.Cmp m = (NumericTask.Cmp) c;
        double[] l = interval(m.left(), lo, hi);
        double[] r = interval(m.right(), lo, hi);
        if (l == null || r == null) return false;
        return switch (m.op()) {
            case "<" -> l[0] < r[1];
            case "<=" -> l[0] <= r[1];
            case ">" -> l[1] > r[0];
            case ">=" -> l[1] >= r[0];
            default -> l[0] <= r[1] && r[0] <= l[1];
        };
    }

    /** The interval of an expression, or null while a fluent it reads has no value yet. */
    static double[] interval(NumericTask.Expr e, double[] lo, double[] hi) {
        if (e instanceof NumericTask.Num n) return new double[] { n.value(), n.value() };
        if (e instanceof NumericTask.Var v) return Double.isNaN(lo[v.fluent()]) ? null : new double[] { lo[v.fluent()], hi[v.fluent()] };
        if (e instanceof NumericTask.Neg n) {
            double[] x = interval(n.operand(), lo, hi);
            return x == null ? null : new double[] { -x[1], -x[0] };
        }
        NumericTask.Bin b = (NumericTask.Bin) e;
        double[] x = interval(b.left(), lo, hi);
        double[] y = interval(b.right(), lo, hi);
        if (x == null || y == null) return null;
        return switch (b.op()) {
            case '+' -> new double[] { x[0] + y[0], x[1] + y[1] };
            case '-' -> new double[] { x[0] - y[1], x[1] - y[0] };
            case '*' -> product(x, y);
            default -> quotient(x, y);
        };
    }

    private static double[] product(double[] x, double[] y) {
        double p1 = x[0] * y[0], p2 = x[0] * y[1], p3 = x[1] * y[0], p4 = x[1] * y[1];
        return new double[] { Math.min(Math.min(p1, p2), Math.min(p3, p4)), Math.max(Math.max(p1, p2), Math.max(p3, p4)) };
    }

    private static double[] quotient(double[] x, double[] y) {
        if (y[0] <= 0 && y[1] >= 0) return new double[] { Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY };
        return product(x, new double[] { 1 / y[1], 1 / y[0] });
    }
}
