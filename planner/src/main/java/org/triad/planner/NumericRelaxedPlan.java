package org.triad.planner;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Metric-FF's relaxed plan for a numeric task (Hoffmann 2003), the estimate its enforced hill-climbing
 * follows: the relaxed graph of {@link NumericHeuristic#explore} gives each operator the first layer it
 * applies; from the goal backwards, a fact is supported by its earliest adder, and a comparison not yet
 * true by the earliest operator that moves its linear form the right way, <em>as many times as the
 * shortfall needs</em> (Metric-FF's repeated achievers: three {@code initialize} steps for a need of 3).
 * Each chosen operator's preconditions become subgoals; one repeated {@code k} times needs what it
 * consumes {@code k} times (an {@code associate} run twice needs twice the substrate), and an achiever that
 * moves back what its consumer moves is left out (it would feed a cycle of shortfalls). The estimate is the
 * number of steps in the relaxed plan; its operators applicable in the state are the helpful actions.
 * <p>
 * Where the layer estimate is the sum of the layers at which the goal's conjuncts first hold, it stays
 * flat while a goal of numbers only (sums of molecule counts) is fed one unit at a time: each
 * {@code initialize} lowers this estimate by one. Comparisons that are not linear, and decreases, are
 * left out (the monotone relaxation); a disjunction follows its first part.
 */
final class NumericRelaxedPlan {
    /** Subgoals handled per evaluation at most (a cycle of operators feeding each other's shortfalls ends here). */
    private static final int MAX_SUBGOALS = 5_000;

    private final NumericTask task;
    private final boolean undoersLast;
    private final NumericHeuristic graph;
    private final int[] opLayer;
    private final int[] goalLayer;
    private final int[] count;
    private final double[] gain;
    private final int[] achiever;
    private final boolean[] marked;
    /** The linear form of each comparison met (null when not linear), by identity. */
    private final Map<NumericTask.Cmp, Form> forms = new IdentityHashMap<>();
    private int[] helpful = new int[0];

    /**
     * A comparison as {@code constant + sum coefs[i] * values[vars[i]]} that holds when at least 0 (above 0
     * when strict); {@code changers}: the operators with an effect on one of its fluents, ascending.
     */
    private record Form(int[] vars, double[] coefs, double constant, boolean strict, int[] changers) { }

    /** Per fluent: the operators with a numeric effect on it (the only achievers a comparison of it can have). */
    private final int[][] changing;

    /** A subgoal and the operator whose precondition it is (-1: the goal). */
    private record Subgoal(NumericTask.Cond cond, int by) { }

    NumericRelaxedPlan(NumericTask task, NumericHeuristic graph) {
        this(task, graph, false);
    }

    /** @param undoersLast whether an achiever that moves back what its consumer moves supports a shortfall nothing else meets */
    NumericRelaxedPlan(NumericTask task, NumericHeuristic graph, boolean undoersLast) {
        this.undoersLast = undoersLast;
        this.task = task;
        this.graph = graph;
        int no = task.ops.size();
        opLayer = new int[no];
        goalLayer = new int[graph.goals().size()];
        count = new int[no];
        gain = new double[task.fluentNames.size()];
        achiever = new int[task.factNames.size()];
        marked = new boolean[task.factNames.size()];
        List<List<Integer>> by = new ArrayList<>();
        for (int f = 0; f < gain.length; f++) by.add(new ArrayList<>());
        for (int o = 0; o < no; o++) {
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (NumericTask.NumEffect n : e.numeric()) {
                    List<Integer> l = by.get(n.fluent());
                    if (l.isEmpty() || l.get(l.size() - 1) != o) l.add(o);
                }
            }
        }
        changing = new int[gain.length][];
        for (int f = 0; f < gain.length; f++) changing[f] = by.get(f).stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * The relaxed plan's length from the state, {@link NumericHeuristic#DEAD_END} when the relaxed graph
     * does not reach the goal; afterwards {@link #helpful()} gives its operators applicable in the state.
     */
    int evaluate(BitSet facts, double[] values) {
        Arrays.fill(opLayer, -1);
        Arrays.fill(goalLayer, -1);
        helpful = new int[0];
        if (graph.explore(facts, values, opLayer, goalLayer) == NumericHeuristic.DEAD_END) return NumericHeuristic.DEAD_END;
        Arrays.fill(count, 0);
        Arrays.fill(gain, 0);
        Arrays.fill(achiever, -1);
        Arrays.fill(marked, false);
        // a fact's supporter: the operator that adds it earliest (ties: the first grounded)
        for (int o = 0; o < opLayer.length; o++) {
            if (opLayer[o] < 0 || task.leftOut != null && task.leftOut[o]) continue;
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (int f : e.adds()) if (!facts.get(f) && (achiever[f] < 0 || opLayer[o] < opLayer[achiever[f]])) achiever[f] = o;
            }
        }
        Deque<Subgoal> open = new ArrayDeque<>();
        List<NumericTask.Cond> goals = graph.goals();
        for (int g = goals.size() - 1; g >= 0; g--) open.push(new Subgoal(goals.get(g), -1));
        int handled = 0;
        while (!open.isEmpty() && handled++ < MAX_SUBGOALS) {
            Subgoal s = open.pop();
            NumericTask.Cond c = s.cond;
            if (c instanceof NumericTask.Fact f) {
                if (!f.positive() || facts.get(f.id()) || marked[f.id()]) continue;
                marked[f.id()] = true;
                int o = achiever[f.id()];
                if (o >= 0 && count[o] == 0) choose(o, 1, values, open);
            } else if (c instanceof NumericTask.All a) {
                for (int i = a.parts().size() - 1; i >= 0; i--) open.push(new Subgoal(a.parts().get(i), s.by));
            } else if (c instanceof NumericTask.Any a) {
                if (!a.parts().isEmpty() && !holds(a, facts, values)) open.push(new Subgoal(a.parts().get(0), s.by));
            } else if (c instanceof NumericTask.Cmp m) {
                shortfall(m, s.by, values, open);
            }
        }
        int steps = 0;
        int n = 0;
        for (int o = 0; o < count.length; o++) {
            steps += count[o];
            if (count[o] > 0 && opLayer[o] == 0) n++;
        }
        helpful = new int[n];
        n = 0;
        for (int o = 0; o < count.length; o++) if (count[o] > 0 && opLayer[o] == 0) helpful[n++] = o;
        return steps;
    }

    /** The relaxed plan's operators applicable in the state last evaluated, ascending. */
    int[] helpful() {
        return helpful;
    }

    /** Adds {@code k} repetitions of {@code o}: its gains count from now on, its preconditions become subgoals. */
    private void choose(int o, int k, double[] values, Deque<Subgoal> open) {
        count[o] += k;
        for (NumericTask.Effects e : task.ops.get(o).effects()) {
            for (NumericTask.NumEffect n : e.numeric()) {
                double up = rise(n, values);
                if (up > 0) gain[n.fluent()] += k * up;
            }
        }
        NumericTask.Cond rest = graph.preRest(o);
        if (rest != NumericTask.TRUE) open.push(new Subgoal(rest, o));
        int[] pf = graph.preFacts(o);
        for (int i = pf.length - 1; i >= 0; i--) open.push(new Subgoal(new NumericTask.Fact(pf[i], true), o));
    }

    /** A comparison's shortfall, given what the relaxed plan already adds, met by repeating its earliest achiever. */
    private void shortfall(NumericTask.Cmp m, int by, double[] values, Deque<Subgoal> open) {
        Form form = forms.computeIfAbsent(m, this::form);
        if (form == null) return;
        double now = form.constant;
        for (int i = 0; i < form.vars.length; i++) {
            double c = form.coefs[i];
            now += c * known(form.vars[i], values) + (c > 0 ? c * gain[form.vars[i]] : 0);
        }
        if (Double.isNaN(now)) return;
        // an operator repeated k times must find what it consumes k times
        double need = -now;
        if (by >= 0 && count[by] > 1) {
            double own = delta(by, form, values, true);
            if (own < 0) need += (count[by] - 1) * -own;
        }
        if (need < 0 || need == 0 && !form.strict) return;
        // an achiever that moves back what the consumer moves is left out: it would feed a cycle of shortfalls
        // (farmland's workers walked between two farms) until the subgoal cap, on every evaluation
        int best = -1;
        double bestDelta = 0;
        for (int o : form.changers) {
            if (o == by || opLayer[o] < 0 || task.leftOut != null && task.leftOut[o] || by >= 0 && undoes(o, by, values)) continue;
            double d = delta(o, form, values, false);
            if (d <= 1e-12) continue;
            if (best < 0 || opLayer[o] < opLayer[best] || opLayer[o] == opLayer[best] && d > bestDelta) {
                best = o;
                bestDelta = d;
            }
        }
        if (best < 0 && undoersLast && by >= 0) {
            // every achiever moves back what the consumer moves (a cart unloads what only loading puts on it):
            // one not yet in the relaxed plan still supports it, so the shortfall is not silently dropped; each
            // operator enters this way at most once, which ends a cycle of shortfalls
            for (int o : form.changers) {
                if (o == by || count[o] > 0 || opLayer[o] < 0 || task.leftOut != null && task.leftOut[o]) continue;
                double d = delta(o, form, values, false);
                if (d <= 1e-12) continue;
                if (best < 0 || opLayer[o] < opLayer[best] || opLayer[o] == opLayer[best] && d > bestDelta) {
                    best = o;
                    bestDelta = d;
                }
            }
        }
        if (best < 0) return;
        double times = need / bestDelta;
        int k = (int) Math.min(10_000, Math.max(1, form.strict && times == Math.floor(times) ? times + 1 : Math.ceil(times - 1e-9)));
        choose(best, k, values, open);
    }

    /**
     * A fluent's value in the state; with {@code undoersLast}, an undefined one counts as the least constant
     * that a reached operator assigns it (a cart's load is 0 once the cart is built), so that a comparison of it
     * still asks for its achievers rather than being dropped.
     */
    private double known(int fluent, double[] values) {
        double v = values[fluent];
        if (!Double.isNaN(v) || !undoersLast) return v;
        for (int o : changing[fluent]) {
            if (opLayer[o] < 0) continue;
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (NumericTask.NumEffect n : e.numeric()) {
                    if (n.fluent() != fluent || !n.kind().equals("assign")) continue;
                    double a = NumericTask.value(n.value(), values);
                    if (Double.isFinite(a) && !(a >= v)) v = a;
                }
            }
        }
        return v;
    }

    /**
     * Whether {@code o} moves back what {@code by} moves (takes away from a fluent {@code by} adds to and
     * adds to one {@code by} takes from: a worker walked back to the farm it came from): such an achiever
     * of {@code by}'s precondition would feed a cycle of shortfalls until the subgoal cap.
     */
    private boolean undoes(int o, int by, double[] values) {
        return moves(o, by, values, true) && moves(o, by, values, false);
    }

    /** Whether {@code o} changes a fluent the other way from {@code by} ({@code byRaises}: one that {@code by} raises). */
    private boolean moves(int o, int by, double[] values, boolean byRaises) {
        for (NumericTask.Effects e : task.ops.get(by).effects()) {
            for (NumericTask.NumEffect n : e.numeric()) {
                double d = change(n, values);
                if (!(byRaises ? d > 0 : d < 0)) continue;
                for (NumericTask.Effects f : task.ops.get(o).effects()) {
                    for (NumericTask.NumEffect m : f.numeric()) {
                        double c = change(m, values);
                        if (m.fluent() == n.fluent() && (byRaises ? c < 0 : c > 0)) return true;
                    }
                }
            }
        }
        return false;
    }

    /** How much one application of {@code o} moves a form (its rises only, unless {@code withFalls}). */
    private double delta(int o, Form form, double[] values, boolean withFalls) {
        double d = 0;
        for (NumericTask.Effects e : task.ops.get(o).effects()) {
            for (NumericTask.NumEffect n : e.numeric()) {
                for (int i = 0; i < form.vars.length; i++) {
                    if (form.vars[i] != n.fluent()) continue;
                    double r = change(n, values);
                    if (!Double.isFinite(r)) continue;
                    double moved = form.coefs[i] * r;
                    if (moved > 0 || withFalls) d += moved;
                }
            }
        }
        return d;
    }

    /** An effect's change of its fluent in the state (an assignment: the new value less the current). */
    private static double change(NumericTask.NumEffect n, double[] values) {
        double a = NumericTask.value(n.value(), values);
        return switch (n.kind()) {
            case "increase" -> a;
            case "decrease" -> -a;
            case "assign" -> a - values[n.fluent()];
            default -> Double.NaN; // scaling: left out of the relaxation
        };
    }

    private static double rise(NumericTask.NumEffect n, double[] values) {
        double r = change(n, values);
        return Double.isFinite(r) && r > 0 ? r : 0;
    }

    private static boolean holds(NumericTask.Cond c, BitSet facts, double[] values) {
        if (c instanceof NumericTask.Fact f) return facts.get(f.id()) == f.positive();
        if (c instanceof NumericTask.All a) return a.parts().stream().allMatch(p -> holds(p, facts, values));
        if (c instanceof NumericTask.Any a) return a.parts().stream().anyMatch(p -> holds(p, facts, values));
        if (c instanceof NumericTask.Const k) return k.value();
        NumericTask.Cmp m = (NumericTask.Cmp) c;
        return NumericTask.holds(m.op(), NumericTask.value(m.left(), values), NumericTask.value(m.right(), values));
    }

    /** The comparison as a form that holds when at least 0, null when it is not linear or an (in)equality. */
    private Form form(NumericTask.Cmp m) {
        double sign;
        switch (m.op()) {
            case ">=", ">" -> sign = 1;
            case "<=", "<" -> sign = -1;
            default -> {
                return null;
            }
        }
        TreeMap<Integer, Double> coefs = new TreeMap<>();
        double k = linear(m.left(), sign, coefs) + linear(m.right(), -sign, coefs);
        if (Double.isNaN(k)) return null;
        List<Integer> vars = new ArrayList<>();
        List<Double> cs = new ArrayList<>();
        coefs.forEach((v, c) -> {
            if (c != 0) {
                vars.add(v);
                cs.add(c);
            }
        });
        java.util.TreeSet<Integer> changers = new java.util.TreeSet<>();
        for (int v : vars) for (int o : changing[v]) changers.add(o);
        return new Form(vars.stream().mapToInt(Integer::intValue).toArray(), cs.stream().mapToDouble(Double::doubleValue).toArray(), k,
                m.op().length() == 1, changers.stream().mapToInt(Integer::intValue).toArray());
    }

    /** Adds {@code factor * e}'s coefficients to {@code coefs}; returns its constant part, NaN when not linear. */
    private static double linear(NumericTask.Expr e, double factor, Map<Integer, Double> coefs) {
        if (e instanceof NumericTask.Num n) return factor * n.value();
        if (e instanceof NumericTask.Var v) {
            coefs.merge(v.fluent(), factor, Double::sum);
            return 0;
        }
        if (e instanceof NumericTask.Neg n) return linear(n.operand(), -factor, coefs);
        NumericTask.Bin b = (NumericTask.Bin) e;
        return switch (b.op()) {
            case '+' -> linear(b.left(), factor, coefs) + linear(b.right(), factor, coefs);
            case '-' -> linear(b.left(), factor, coefs) + linear(b.right(), -factor, coefs);
            case '*' -> b.left() instanceof NumericTask.Num n ? linear(b.right(), factor * n.value(), coefs)
                    : b.right() instanceof NumericTask.Num n ? linear(b.left(), factor * n.value(), coefs) : Double.NaN;
            case '/' -> b.right() instanceof NumericTask.Num n && n.value() != 0 ? linear(b.left(), factor / n.value(), coefs) : Double.NaN;
            default -> Double.NaN;
        };
    }
}
