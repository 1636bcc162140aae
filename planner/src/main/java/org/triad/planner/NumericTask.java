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
import org.triad.planner.pddl.PlanMetric;
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

    record Op(String name, List<String> args, Cond pre, List<Effects> effects) {
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
    /**
     * The metric to minimise (a maximised one negated), over the state's values; null without a
     * {@code :metric}. {@code (total-cost)} and {@code (total-time)} are fluents of the state here.
     */
    Expr metric;
    /**
     * Fluents that only accumulate: changed only by {@code increase}/{@code decrease}, read by no
     * condition, goal or effect and only linearly by the metric ({@code total-cost}, fuel used). Two
     * states that differ only in them have the same future, so the search keeps the cheaper one.
     */
    boolean[] accumulator;
    /** Per fluent, how much the metric grows when the fluent grows by one (0 for fluents it does not read linearly). */
    double[] metricWeight;
    /**
     * Instances the search leaves out ({@link NumericDominatedOps}: a kept one does all they do that
     * matters), null for none; set by the search, read by its successor index and admissible bound.
     */
    boolean[] leftOut;
    /** The instances' shapes for {@link NumericDominatedOps}, computed once with a cached grounding (null: computed per search). */
    NumericDominatedOps.Shapes opShapes;

    private final Map<String, Integer> factIds = new HashMap<>();
    private final Map<String, Integer> fluentIds = new LinkedHashMap<>();
    private final Map<String, Double> initFluents = new HashMap<>();
    private final Set<String> staticFacts = new HashSet<>();
    private final Set<String> changedPredicates = new HashSet<>();
    private final Set<String> changedFunctions = new HashSet<>();
    private final Set<String> assignedFunctions = new HashSet<>();
    private final ObjectUniverse universe;
    /** Partial parameter bindings tried while grounding, at most {@link #MAX_BINDINGS} (a work bound, not a time bound). */
    private long bindings;
    static final long MAX_BINDINGS = 5_000_000;

    NumericTask(Domain domain, Problem problem) {
        if (!domain.axioms().isEmpty()) throw new PlanningInputException("derived predicates together with numeric fluents are not supported");
        universe = new ObjectUniverse(domain, problem);
        changes(domain, changedPredicates, changedFunctions, assignedFunctions);
        PlanMetric planMetric = PlanMetric.of(problem);
        countsSteps = planMetric != null && planMetric.fluents().stream().anyMatch(f -> f.name().equals(PlanMetric.TOTAL_TIME));
        if (countsSteps) changedFunctions.add(PlanMetric.TOTAL_TIME);
        initialValues(problem, planMetric);
        for (Formula.Atom a : problem.init()) {
            String key = PddlWriter.atom(a);
            if (changedPredicates.contains(a.predicate())) initFacts.add(fact(key));
            else {
                staticFacts.add(key);
                for (int k = 0; k < a.args().size(); k++) {
                    staticIndex.computeIfAbsent(a.predicate() + "/" + k + "/" + a.args().get(k), x -> new ArrayList<>()).add(a.args());
                }
            }
        }
        for (Action a : domain.actions()) ground(a);
        opsRead = new boolean[fluentNames.size()];
        opsOnlyAccumulate = new boolean[fluentNames.size()];
        java.util.Arrays.fill(opsOnlyAccumulate, true);
        for (Op op : ops) {
            reads(op.pre(), opsRead);
            for (Effects e : op.effects()) {
                reads(e.when(), opsRead);
                for (NumEffect x : e.numeric()) {
                    reads(x.value(), opsRead);
                    if (!x.kind().equals("increase") && !x.kind().equals("decrease")) opsOnlyAccumulate[x.fluent()] = false;
                }
            }
        }
        goalAndMetric(problem, planMetric);
    }

    /**
     * The same grounding for another problem that {@link NumericGroundingCache} found to share everything
     * grounding reads: the domain, objects, static facts, the values of fluents no action changes, which
     * changed fluents have a value, and the metric. Only the initial state, the goal and the metric's
     * consequences (accumulators) are the problem's own; the instances are shared (never changed after
     * grounding), the numbering is copied (a goal may name facts or fluents no instance does).
     */
    NumericTask(NumericTask grounded, Problem problem) {
        universe = grounded.universe;
        countsSteps = grounded.countsSteps;
        ops.addAll(grounded.ops);
        factNames.addAll(grounded.factNames);
        factIds.putAll(grounded.factIds);
        fluentNames.addAll(grounded.fluentNames);
        fluentIds.putAll(grounded.fluentIds);
        staticFacts.addAll(grounded.staticFacts);
        changedPredicates.addAll(grounded.changedPredicates);
        changedFunctions.addAll(grounded.changedFunctions);
        assignedFunctions.addAll(grounded.assignedFunctions);
        undefinedReads.putAll(grounded.undefinedReads);
        opsRead = grounded.opsRead;
        opShapes = grounded.opShapes;
        opsOnlyAccumulate = grounded.opsOnlyAccumulate;
        PlanMetric planMetric = PlanMetric.of(problem);
        initialValues(problem, planMetric);
        for (Formula.Atom a : problem.init()) {
            if (changedPredicates.contains(a.predicate())) initFacts.add(fact(PddlWriter.atom(a)));
        }
        goalAndMetric(problem, planMetric);
    }

    private void initialValues(Problem problem, PlanMetric planMetric) {
        for (Problem.NumericFact f : problem.numericInit()) {
            String key = NumericValues.key(f.function(), f.args());
            if (!Double.isFinite(f.value())) throw new PlanningInputException("(" + key + ") is not a finite number in :init");
            initFluents.put(key, f.value());
        }
        // an accumulator the problem does not start is 0, as Metric-FF and VAL take total-cost
        if (changedFunctions.contains(PlanMetric.TOTAL_COST)
                || planMetric != null && planMetric.fluents().stream().anyMatch(f -> f.name().equals(PlanMetric.TOTAL_COST))) {
            initFluents.putIfAbsent(PlanMetric.TOTAL_COST, 0.0);
        }
        if (countsSteps) initFluents.put(PlanMetric.TOTAL_TIME, 0.0);
    }

    private void goalAndMetric(Problem problem, PlanMetric planMetric) {
        try {
            goal = cond(problem.goal(), Map.of(), false, "the goal");
        } catch (Undefined e) {
            throw new PlanningInputException("the goal reads " + e.getMessage() + ", which :init gives no value and no action sets");
        }
        if (planMetric != null) {
            try {
                Expr m = expr(planMetric.expression(), Map.of(), "the metric");
                metric = planMetric.minimize() ? m : new Neg(m);
            } catch (Undefined e) {
                throw new PlanningInputException("the metric reads " + e.getMessage() + ", which :init gives no value and no action sets");
            }
        }
        initValues = new double[fluentNames.size()];
        for (int i = 0; i < fluentNames.size(); i++) initValues[i] = initFluents.getOrDefault(fluentNames.get(i), Double.NaN);
        findAccumulators();
    }

    /** Predicates and functions some action's effects change, and the functions some action assigns. */
    static void changes(Domain domain, Set<String> predicates, Set<String> functions, Set<String> assigned) {
        for (Action a : domain.actions()) changes(a.effects(), predicates, functions, assigned);
    }

    private final boolean countsSteps;
    /**
     * Per fluent of the grounding (before a goal adds any): whether an instance reads it, and whether
     * every instance only increases or decreases it; the instances' share of {@link #findAccumulators},
     * kept with a cached grounding.
     */
    private boolean[] opsRead;
    private boolean[] opsOnlyAccumulate;
    /** Per fluent without a value, the actions whose instances read it (so never apply), with their numbers. */
    private final Map<String, Map<String, Integer>> undefinedReads = new LinkedHashMap<>();

    /**
     * Why instances are missing, for a "no plan" answer: {@code (battery r2) has no value in :init (and no
     * action assigns it), so 2 instances of 'drive' that read it never apply}; empty when none is.
     */
    String undefinedNote() {
        if (undefinedReads.isEmpty()) return "";
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, Map<String, Integer>> e : undefinedReads.entrySet()) {
            if (parts.size() == 3) {
                parts.add("and " + (undefinedReads.size() - 3) + " more fluents");
                break;
            }
            List<String> users = new ArrayList<>();
            e.getValue().forEach((action, n) -> users.add(n + " instance" + (n == 1 ? "" : "s") + " of '" + action + "'"));
            parts.add(e.getKey() + " has no value in :init (and no action assigns it), so " + String.join(" and ", users) + " that read it never apply");
        }
        return "; " + String.join("; ", parts);
    }

    private void findAccumulators() {
        int n = fluentNames.size();
        accumulator = new boolean[n];
        metricWeight = new double[n];
        // fluents the goal or metric added after grounding: no instance reads or changes them
        boolean[] read = java.util.Arrays.copyOf(opsRead, n);
        boolean[] onlyAccumulates = java.util.Arrays.copyOf(opsOnlyAccumulate, n);
        java.util.Arrays.fill(onlyAccumulates, opsOnlyAccumulate.length, n, true);
        reads(goal, read);
        boolean[] linear = new boolean[n];
        if (metric != null) linearIn(metric, true, linear, read);
        for (int f = 0; f < n; f++) {
            accumulator[f] = !read[f] && onlyAccumulates[f] && (metric == null || linear[f] || !mentions(metric, f));
        }
        if (metric != null) {
            double[] zero = new double[n];
            double base = value(metric, zero);
            for (int f = 0; f < n; f++) {
                if (!linear[f]) continue;
                zero[f] = 1;
                metricWeight[f] = value(metric, zero) - base;
                zero[f] = 0;
            }
        }
    }

    private static void reads(Cond c, boolean[] read) {
        if (c instanceof Cmp m) {
            reads(m.left(), read);
            reads(m.right(), read);
        } else if (c instanceof All a) a.parts().forEach(p -> reads(p, read));
        else if (c instanceof Any a) a.parts().forEach(p -> reads(p, read));
    }

    private static void reads(Expr e, boolean[] read) {
        if (e instanceof Var v) read[v.fluent()] = true;
        else if (e instanceof Neg x) reads(x.operand(), read);
        else if (e instanceof Bin b) {
            reads(b.left(), read);
            reads(b.right(), read);
        }
    }

    static boolean mentions(Expr e, int f) {
        if (e instanceof Var v) return v.fluent() == f;
        if (e instanceof Neg x) return mentions(x.operand(), f);
        if (e instanceof Bin b) return mentions(b.left(), f) || mentions(b.right(), f);
        return false;
    }

    /** Marks the fluents {@code e} reads linearly ({@code ok}: so far only under {@code + -} or a constant factor); any other use counts as a read. */
    private static void linearIn(Expr e, boolean ok, boolean[] linear, boolean[] read) {
        if (e instanceof Var v) {
            if (ok) linear[v.fluent()] = true; else read[v.fluent()] = true;
        } else if (e instanceof Neg x) linearIn(x.operand(), ok, linear, read);
        else if (e instanceof Bin b) {
            boolean lin = b.op() == '+' || b.op() == '-' || b.op() == '*' && (b.left() instanceof Num || b.right() instanceof Num)
                    || b.op() == '/' && b.right() instanceof Num;
            linearIn(b.left(), ok && lin, linear, read);
            linearIn(b.right(), ok && lin, linear, read);
        }
    }

    /** The metric's value (to minimise) for the state's values; 0 without a metric. */
    double metricValue(double[] values) {
        return metric == null ? 0 : value(metric, values);
    }

    /** The value of a ground expression; NaN for an undefined fluent or a division by zero. */
    static double value(Expr e, double[] values) {
        if (e instanceof Num n) return n.value();
        if (e instanceof Var v) return values[v.fluent()];
        if (e instanceof Neg n) return -value(n.operand(), values);
        Bin b = (Bin) e;
        double l = value(b.left(), values);
        double r = value(b.right(), values);
        return switch (b.op()) {
            case '+' -> l + r;
            case '-' -> l - r;
            case '*' -> l * r;
            default -> r == 0 ? Double.NaN : l / r;
        };
    }

    private static void changes(List<PddlEffect> effects, Set<String> predicates, Set<String> functions, Set<String> assigned) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add a) predicates.add(a.atom().predicate());
            else if (e instanceof PddlEffect.Delete d) predicates.add(d.atom().predicate());
            else if (e instanceof PddlEffect.Forall q) changes(q.body(), predicates, functions, assigned);
            else if (e instanceof PddlEffect.Increase i) functions.add(i.function());
            else if (e instanceof PddlEffect.When w) changes(w.body(), predicates, functions, assigned);
            else if (e instanceof PddlEffect.NumericEffect n) {
                functions.add(n.target().name());
                if (n.kind().equals("assign")) assigned.add(n.target().name());
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
        int[] candidates = universe.ofTypes(p.types());
        int[] joined = joined(p, b, conjuncts);
        if (joined != null && joined.length < candidates.length) candidates = joined;
        for (int o : candidates) {
            b.put(p.name(), universe.names.get(o));
            bind(a, i + 1, b, conjuncts);
        }
        b.remove(p.name());
    }

    /**
     * The objects parameter {@code p} can take by a static atom of the precondition whose other arguments
     * are bound (a move's destination among the places adjacent to its bound source), ascending and of
     * its type; null when no such atom narrows it. Without this a move over N places tried N² bindings.
     */
    private int[] joined(TypedName p, Map<String, String> b, List<Formula> conjuncts) {
        int[] best = null;
        for (Formula c : conjuncts) {
            if (!(c instanceof Formula.Atom at) || changedPredicates.contains(at.predicate()) || !at.args().contains(p.name())) continue;
            int key = -1;
            boolean usable = true;
            for (int k = 0; k < at.args().size() && usable; k++) {
                String t = at.args().get(k);
                if (t.equals(p.name())) continue;
                if (t.startsWith("?") && !b.containsKey(t)) usable = false;
                else if (key < 0) key = k;
            }
            if (!usable || key < 0) continue;
            List<List<String>> rows = staticIndex.getOrDefault(at.predicate() + "/" + key + "/" + b.getOrDefault(at.args().get(key), at.args().get(key)), List.of());
            java.util.TreeSet<Integer> out = new java.util.TreeSet<>();
            for (List<String> row : rows) {
                String value = null;
                boolean match = row.size() == at.args().size();
                for (int k = 0; k < at.args().size() && match; k++) {
                    String t = at.args().get(k);
                    if (t.equals(p.name())) {
                        if (value == null) value = row.get(k);
                        else match = value.equals(row.get(k));
                    } else {
                        match = row.get(k).equals(b.getOrDefault(t, t));
                    }
                }
                Integer id = match && value != null ? universe.ids.get(value) : null;
                if (id != null && universe.isOf(id, p.types())) out.add(id);
            }
            if (best == null || out.size() < best.length) best = out.stream().mapToInt(Integer::intValue).toArray();
        }
        return best;
    }

    /** Static atoms by predicate, argument position and the argument there. */
    private final Map<String, List<List<String>>> staticIndex = new HashMap<>();

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
            effects(a.effects(), b, TRUE, effects, label);
            if (countsSteps) effects.add(new Effects(TRUE, new int[0], new int[0], List.of(new NumEffect("increase", fluent(PlanMetric.TOTAL_TIME), new Num(1)))));
            ops.add(new Op(a.name(), args, pre, effects));
        } catch (Undefined e) {
            // reads a fluent that never has a value: never applicable (PDDL 2.1), said when no plan is found
            undefinedReads.computeIfAbsent(e.getMessage(), k -> new LinkedHashMap<>()).merge(a.name(), 1, Integer::sum);
        }
    }

    private void effects(List<PddlEffect> list, Map<String, String> b, Cond when, List<Effects> out, String label) {
        List<Integer> adds = new ArrayList<>();
        List<Integer> dels = new ArrayList<>();
        List<NumEffect> numeric = new ArrayList<>();
        for (PddlEffect e : list) {
            if (e instanceof PddlEffect.Add a) adds.add(fact(ground(a.atom(), b)));
            else if (e instanceof PddlEffect.Delete d) dels.add(fact(ground(d.atom(), b)));
            else if (e instanceof PddlEffect.Forall q) {
                for (Map<String, String> nb : new Normalizer(universe).bindings(q.variables(), b)) effects(q.body(), nb, when, out, label);
            } else if (e instanceof PddlEffect.When w) {
                Cond c = cond(w.condition(), b, false, label);
                if (c != FALSE) effects(w.body(), b, c == TRUE ? when : all(List.of(when, c)), out, label);
            } else if (e instanceof PddlEffect.Increase inc) {
                // an action cost: total-cost is a fluent like the others here (an accumulator, see findAccumulators)
                NumericExpr amount = inc.amount() instanceof NumericTerm.Constant c ? new NumericExpr.Number(c.value())
                        : new NumericExpr.Fluent(((NumericTerm.Function) inc.amount()).name(), ((NumericTerm.Function) inc.amount()).args());
                numeric.add(new NumEffect("increase", fluent(inc.function()), expr(amount, b, label)));
            } else if (e instanceof PddlEffect.NumericEffect n) {
                numeric.add(new NumEffect(n.kind(), fluent(groundFluent(n.target(), b)), expr(n.value(), b, label)));
            }
        }
        if (!adds.isEmpty() || !dels.isEmpty() || !numeric.isEmpty()) {
            out.add(new Effects(when, adds.stream().mapToInt(Integer::intValue).toArray(), dels.stream().mapToInt(Integer::intValue).toArray(),
                    numeric));
        }
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
        // by characters, not a switch on the string: the search checks every successor's comparisons
        boolean strict = op.length() == 1;
        return switch (op.charAt(0)) {
            case '<' -> strict ? l < r : l <= r;
            case '>' -> strict ? l > r : l >= r;
            case '!' -> l != r;
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
