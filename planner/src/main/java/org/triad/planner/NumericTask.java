package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.NumericExpr;
import org.triad.planner.pddl.NumericTerm;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * A PDDL 2.1 (level 2) task grounded for {@link NumericSearch}: facts and fluents numbered, every action
 * instance whose precondition can hold with its conditions compiled ({@link Cond}), its effects, numeric
 * effects and its cost. Static facts, {@code =} between objects and fluents no action changes are folded
 * away while grounding (a distance table becomes constants). An instance that reads a fluent without a
 * value (none in {@code :init}, and no action assigns it) can never apply, as in PDDL 2.1, and is left out;
 * a goal that reads one is a {@link PlanningInputException} naming the fluent.
 */
final class NumericTask {
    /** A ground condition. */
    sealed interface Cond permits Fact, Cmp, All, Any, Const { }

    record Fact(int id, boolean positive) implements Cond { }

    record Cmp(String op, Expr left, Expr right) implements Cond { }

    record All(List<Cond> parts) implements Cond { }

    record Any(List<Cond> parts) implements Cond { }

    record Const(boolean value) implements Cond { }

    static final Const TRUE = new Const(true);
    static final Const FALSE = new Const(false);

    /** A ground numeric expression: {@code fluent} indexes the state's values. */
    sealed interface Expr permits Num, Var, Bin, Neg { }

    record Num(double value) implements Expr { }

    record Var(int fluent) implements Expr { }

    record Bin(char op, Expr left, Expr right) implements Expr { }

    record Neg(Expr operand) implements Expr { }

    record NumEffect(String kind, int fluent, Expr value) { }

    /** Effects of an instance, unconditional ({@code when} is TRUE) or conditional. */
    record Effects(Cond when, int[] adds, int[] dels, List<NumEffect> numeric) { }

    record Op(String name, List<String> args, Cond pre, List<Effects> effects, double cost) {
        String label() {
            return "(" + name + (args.isEmpty() ? "" : " " + String.join(" ", args)) + ")";
        }
    }

    final List<String> factNames = new ArrayList<>();
    final List<String> fluentNames = new ArrayList<>();
    final List<Op> ops = new ArrayList<>();
    final Set<Integer> initFacts = new HashSet<>();
    double[] initValues;
    Cond goal;

    private final Map<String, Integer> factIds = new HashMap<>();
    private final Map<String, Integer> fluentIds = new LinkedHashMap<>();
    private final Map<String, Double> initFluents = new HashMap<>();
    private final Set<String> staticFacts = new HashSet<>();
    private final Set<String> changedPredicates = new HashSet<>();
    private final Set<String> changedFunctions = new HashSet<>();
    private final Set<String> assignedFunctions = new HashSet<>();
    private final ObjectUniverse universe;
    private final Map<String, Double> constantCosts = new HashMap<>();
    /** Partial parameter bindings tried while grounding, at most {@link #MAX_BINDINGS} (a work bound, not a time bound). */
    private long bindings;
    static final long MAX_BINDINGS = 5_000_000;

    NumericTask(Domain domain, Problem problem) {
        if (!domain.axioms().isEmpty()) throw new PlanningInputException("derived predicates together with numeric fluents are not supported");
        universe = new ObjectUniverse(domain, problem);
        for (Action a : domain.actions()) changes(a.effects());
        for (Problem.NumericFact f : problem.numericInit()) {
            String key = NumericValues.key(f.function(), f.args());
            if (!Double.isFinite(f.value())) throw new PlanningInputException("(" + key + ") is not a finite number in :init");
            initFluents.put(key, f.value());
            constantCosts.put(key, f.value());
        }
        for (Formula.Atom a : problem.init()) {
            String key = PddlWriter.atom(a);
            if (changedPredicates.contains(a.predicate())) initFacts.add(fact(key));
            else staticFacts.add(key);
        }
        for (Action a : domain.actions()) ground(a);
        try {
            goal = cond(problem.goal(), Map.of(), false, "the goal");
        } catch (Undefined e) {
            throw new PlanningInputException("the goal reads " + e.getMessage() + ", which :init gives no value and no action sets");
        }
        initValues = new double[fluentNames.size()];
        for (int i = 0; i < fluentNames.size(); i++) initValues[i] = initFluents.getOrDefault(fluentNames.get(i), Double.NaN);
    }

    private void changes(List<PddlEffect> effects) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add a) changedPredicates.add(a.atom().predicate());
            else if (e instanceof PddlEffect.Delete d) changedPredicates.add(d.atom().predicate());
            else if (e instanceof PddlEffect.Forall q) changes(q.body());
            else if (e instanceof PddlEffect.When w) changes(w.body());
            else if (e instanceof PddlEffect.NumericEffect n) {
                changedFunctions.add(n.target().name());
                if (n.kind().equals("assign")) assignedFunctions.add(n.target().name());
            }
        }
    }

    private int fact(String key) {
        Integer id = factIds.get(key);
        if (id != null) return id;
        factIds.put(key, factNames.size());
        factNames.add(key);
        return factNames.size() - 1;
    }

    private int fluent(String key) {
        Integer id = fluentIds.get(key);
        if (id != null) return id;
        fluentIds.put(key, fluentNames.size());
        fluentNames.add(key);
        return fluentNames.size() - 1;
    }

    /** Every binding of the action's parameters, pruned by the static atoms and equalities of its precondition. */
    private void ground(Action a) {
        List<Formula> conjuncts = new ArrayList<>();
        flatten(a.precondition(), conjuncts);
        bind(a, 0, new LinkedHashMap<>(), conjuncts);
    }

    private static void flatten(Formula f, List<Formula> out) {
        if (f instanceof Formula.And and) and.parts().forEach(p -> flatten(p, out));
        else out.add(f);
    }

    private void bind(Action a, int i, Map<String, String> b, List<Formula> conjuncts) {
        if (++bindings > MAX_BINDINGS) {
            throw new PlanningInputException("grounding action '" + a.name() + "' passes " + MAX_BINDINGS
                    + " partial bindings; the task is too large for numeric planning");
        }
        for (Formula c : conjuncts) {
            if (isStaticTest(c) && bound(c, b) && cond(c, b, false, null) == FALSE) return;
        }
        if (i == a.parameters().size()) {
            instantiate(a, b);
            return;
        }
        TypedName p = a.parameters().get(i);
        for (int o : universe.ofTypes(p.types())) {
            b.put(p.name(), universe.names.get(o));
            bind(a, i + 1, b, conjuncts);
        }
        b.remove(p.name());
    }

    private boolean isStaticTest(Formula c) {
        return c instanceof Formula.Atom at && !changedPredicates.contains(at.predicate()) || c instanceof Formula.Equals
                || c instanceof Formula.Not n && (n.body() instanceof Formula.Equals
                || n.body() instanceof Formula.Atom at2 && !changedPredicates.contains(at2.predicate()));
    }

    private static boolean bound(Formula c, Map<String, String> b) {
        List<String> terms = new ArrayList<>();
        Formula f = c instanceof Formula.Not n ? n.body() : c;
        if (f instanceof Formula.Atom at) terms.addAll(at.args());
        if (f instanceof Formula.Equals e) terms.addAll(List.of(e.left(), e.right()));
        for (String t : terms) if (t.startsWith("?") && !b.containsKey(t)) return false;
        return true;
    }

    private void instantiate(Action a, Map<String, String> b) {
        List<String> args = new ArrayList<>();
        for (TypedName p : a.parameters()) args.add(b.get(p.name()));
        String label = "(" + a.name() + (args.isEmpty() ? "" : " " + String.join(" ", args)) + ")";
        try {
            Cond pre = cond(a.precondition(), b, false, label);
            if (pre == FALSE) return;
            List<Effects> effects = new ArrayList<>();
            double[] cost = {0};
            effects(a.effects(), b, TRUE, effects, cost, label);
            ops.add(new Op(a.name(), args, pre, effects, cost[0]));
        } catch (Undefined e) {
            // reads a fluent that never has a value: never applicable
        }
    }

    private void effects(List<PddlEffect> list, Map<String, String> b, Cond when, List<Effects> out, double[] cost, String label) {
        List<Integer> adds = new ArrayList<>();
        List<Integer> dels = new ArrayList<>();
        List<NumEffect> numeric = new ArrayList<>();
        for (PddlEffect e : list) {
            if (e instanceof PddlEffect.Add a) adds.add(fact(ground(a.atom(), b)));
            else if (e instanceof PddlEffect.Delete d) dels.add(fact(ground(d.atom(), b)));
            else if (e instanceof PddlEffect.Forall q) {
                for (Map<String, String> nb : new Normalizer(universe).bindings(q.variables(), b)) effects(q.body(), nb, when, out, cost, label);
            } else if (e instanceof PddlEffect.When w) {
                Cond c = cond(w.condition(), b, false, label);
                if (c != FALSE) effects(w.body(), b, c == TRUE ? when : all(List.of(when, c)), out, cost, label);
            } else if (e instanceof PddlEffect.Increase inc) {
                cost[0] += costOf(inc.amount(), b, label);
            } else if (e instanceof PddlEffect.NumericEffect n && n.kind().equals("increase") && n.target().name().equals("total-cost")
                    && n.target().args().isEmpty()) {
                // the metric's accumulator is not part of the state (every state would differ by its cost);
                // a cost that depends on the state counts as 0 for the tie-breaking cost of the search
                Expr amount = expr(n.value(), b, label);
                if (amount instanceof Num v) cost[0] += v.value();
            } else if (e instanceof PddlEffect.NumericEffect n) {
                numeric.add(new NumEffect(n.kind(), fluent(groundFluent(n.target(), b)), expr(n.value(), b, label)));
            }
        }
        if (!adds.isEmpty() || !dels.isEmpty() || !numeric.isEmpty()) {
            out.add(new Effects(when, adds.stream().mapToInt(Integer::intValue).toArray(), dels.stream().mapToInt(Integer::intValue).toArray(),
                    numeric));
        }
    }

    private double costOf(NumericTerm t, Map<String, String> b, String label) {
        if (t instanceof NumericTerm.Constant c) return c.value();
        NumericTerm.Function f = (NumericTerm.Function) t;
        List<String> args = new ArrayList<>();
        for (String x : f.args()) args.add(b.getOrDefault(x, x));
        Double v = constantCosts.get(NumericValues.key(f.name(), args));
        if (v == null) throw new Undefined("(" + NumericValues.key(f.name(), args) + ")"); // as in PDDL 2.1: never applicable
        return v;
    }

    private static String ground(Formula.Atom a, Map<String, String> b) {
        List<String> args = new ArrayList<>();
        for (String t : a.args()) args.add(b.getOrDefault(t, t));
        return PddlWriter.atom(new Formula.Atom(a.predicate(), args));
    }

    private static String groundFluent(NumericExpr.Fluent f, Map<String, String> b) {
        List<String> args = new ArrayList<>();
        for (String t : f.args()) args.add(b.getOrDefault(t, t));
        return NumericValues.key(f.name(), args);
    }

    /** The ground condition of {@code f} (negated if {@code neg}), folded where static; {@code label} names its owner in errors. */
    private Cond cond(Formula f, Map<String, String> b, boolean neg, String label) {
        if (f instanceof Formula.Atom a) {
            String key = ground(a, b);
            if (!changedPredicates.contains(a.predicate())) return staticFacts.contains(key) != neg ? TRUE : FALSE;
            return new Fact(fact(key), !neg);
        }
        if (f instanceof Formula.Equals e) return b.getOrDefault(e.left(), e.left()).equals(b.getOrDefault(e.right(), e.right())) != neg ? TRUE : FALSE;
        if (f instanceof Formula.Not n) return cond(n.body(), b, !neg, label);
        if (f instanceof Formula.And and) {
            List<Cond> parts = new ArrayList<>();
            for (Formula p : and.parts()) parts.add(cond(p, b, neg, label));
            return neg ? any(parts) : all(parts);
        }
        if (f instanceof Formula.Or or) {
            List<Cond> parts = new ArrayList<>();
            for (Formula p : or.parts()) parts.add(cond(p, b, neg, label));
            return neg ? all(parts) : any(parts);
        }
        if (f instanceof Formula.Imply i) {
            return cond(new Formula.Or(List.of(new Formula.Not(i.condition()), i.consequence())), b, neg, label);
        }
        if (f instanceof Formula.Compare c) {
            if (label == null) return TRUE; // while pruning bindings: decided once the instance is complete
            Expr l = expr(c.left(), b, label);
            Expr r = expr(c.right(), b, label);
            String op = neg ? switch (c.op()) {
                case "<" -> ">=";
                case "<=" -> ">";
                case ">" -> "<=";
                case ">=" -> "<";
                default -> "!=";
            } : c.op();
            if (l instanceof Num x && r instanceof Num y) return holds(op, x.value(), y.value()) ? TRUE : FALSE;
            return op.equals("!=") ? any(List.of(new Cmp("<", l, r), new Cmp(">", l, r))) : new Cmp(op, l, r);
        }
        boolean universal = f instanceof Formula.Forall;
        List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
        Formula body = universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body();
        List<Cond> parts = new ArrayList<>();
        for (Map<String, String> nb : new Normalizer(universe).bindings(vars, b)) parts.add(cond(body, nb, neg, label));
        return universal != neg ? all(parts) : any(parts);
    }

    static boolean holds(String op, double l, double r) {
        return switch (op) {
            case "<" -> l < r;
            case "<=" -> l <= r;
            case ">" -> l > r;
            case ">=" -> l >= r;
            case "!=" -> l != r;
            default -> l == r;
        };
    }

    private Expr expr(NumericExpr e, Map<String, String> b, String label) {
        if (e instanceof NumericExpr.Number n) return new Num(n.value());
        if (e instanceof NumericExpr.Fluent f) {
            String key = groundFluent(f, b);
            Double init = initFluents.get(key);
            if (init == null && !assignedFunctions.contains(f.name())) throw new Undefined("(" + key + ")");
            if (!changedFunctions.contains(f.name())) return new Num(init);
            return new Var(fluent(key));
        }
        if (e instanceof NumericExpr.Negation n) {
            Expr x = expr(n.operand(), b, label);
            return x instanceof Num v ? new Num(-v.value()) : new Neg(x);
        }
        NumericExpr.Arithmetic a = (NumericExpr.Arithmetic) e;
        Expr l = expr(a.left(), b, label);
        Expr r = expr(a.right(), b, label);
        if (a.op() == '/' && r instanceof Num z && z.value() == 0) {
            throw new PlanningInputException(label + " divides by zero: " + PddlWriter.expression(a));
        }
        if (l instanceof Num x && r instanceof Num y) {
            double v = switch (a.op()) {
                case '+' -> x.value() + y.value();
                case '-' -> x.value() - y.value();
                case '*' -> x.value() * y.value();
                default -> x.value() / y.value();
            };
            if (!Double.isFinite(v)) throw new PlanningInputException(label + ": " + PddlWriter.expression(a) + " overflows");
            return new Num(v);
        }
        return new Bin(a.op(), l, r);
    }

    /** A fluent that has no value in any reachable state. */
    private static final class Undefined extends RuntimeException {
        Undefined(String fluent) {
            super(fluent, null, false, false);
        }
    }

    private static Cond all(List<Cond> parts) {
        List<Cond> out = new ArrayList<>();
        for (Cond c : parts) {
            if (c == FALSE) return FALSE;
            if (c instanceof All a) out.addAll(a.parts());
            else if (c != TRUE) out.add(c);
        }
        return out.isEmpty() ? TRUE : out.size() == 1 ? out.get(0) : new All(out);
    }

    private static Cond any(List<Cond> parts) {
        List<Cond> out = new ArrayList<>();
        for (Cond c : parts) {
            if (c == TRUE) return TRUE;
            if (c != FALSE) out.add(c);
        }
        return out.isEmpty() ? FALSE : out.size() == 1 ? out.get(0) : new Any(out);
    }
}
