package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.NumericExpr;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.pddl.PlanMetric;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Replays a plan on the lifted domain (independently of the grounder): checks each step's action,
 * argument types and precondition (any ADL formula), collects the effects whose {@code when}
 * conditions hold in the state before the step, applies all deletes then all adds, and checks the
 * goal at the end. Numeric fluents (PDDL 2.1) are replayed too: comparisons are evaluated in the state
 * before the step, numeric effects read their values there and apply with the others; a fluent without
 * a value, a division by zero or a result that is not a finite number makes the plan invalid at that step.
 */
public final class PlanValidator {
    private PlanValidator() { }

    /** {@code failedStep} is the 0-based index of the first bad step, or -1. */
    public record Report(boolean valid, int failedStep, String message, boolean goalReached) {
        @Override
        public String toString() {
            return valid ? "valid" : message;
        }
    }

    public static Report validate(Domain domain, Problem problem, PddlPlan plan) {
        return replay(domain, problem, plan, new HashMap<>());
    }

    /**
     * The value of the problem's {@code :metric} at the end of a valid plan (a maximised metric as it is,
     * not negated); empty when the problem has no metric or the plan is not valid. {@code (total-cost)}
     * sums the plan's action costs (0 when {@code :init} does not start it), {@code (total-time)} counts
     * its steps.
     */
    public static java.util.OptionalDouble metricValue(Domain domain, Problem problem, PddlPlan plan) {
        PlanMetric metric = PlanMetric.of(problem);
        if (metric == null) return java.util.OptionalDouble.empty();
        Map<String, Double> fluents = new HashMap<>();
        if (!replay(domain, problem, plan, fluents).valid()) return java.util.OptionalDouble.empty();
        fluents.put(PlanMetric.TOTAL_TIME, (double) plan.length());
        fluents.putIfAbsent(PlanMetric.TOTAL_COST, 0.0);
        try {
            return java.util.OptionalDouble.of(NumericValues.evaluate(metric.expression(), f -> {
                Double v = fluents.get(NumericValues.key(f.name(), f.args()));
                if (v == null) throw new NumericValues.Fault("the metric reads (" + NumericValues.key(f.name(), f.args()) + "), which has no value");
                return v;
            }));
        } catch (NumericValues.Fault e) {
            return java.util.OptionalDouble.empty();
        }
    }

    /** Validates {@code plan}, leaving the fluents' values at its end in {@code fluents}. */
    private static Report replay(Domain domain, Problem problem, PddlPlan plan, Map<String, Double> fluents) {
        ObjectUniverse universe;
        try {
            universe = new ObjectUniverse(domain, problem);
        } catch (PlanningInputException e) {
            return new Report(false, -1, e.getMessage(), false);
        }
        Set<Formula.Atom> state = new HashSet<>(problem.init());
        for (Problem.NumericFact f : problem.numericInit()) fluents.put(NumericValues.key(f.function(), f.args()), f.value());
        Evaluator ev = new Evaluator(universe, state, fluents);
        Map<String, Integer> strata;
        try {
            strata = DerivedStrata.of(domain);
        } catch (PlanningInputException e) {
            return new Report(false, -1, e.getMessage(), false);
        }
        ev.derive(domain, strata);
        for (int i = 0; i < plan.steps().size(); i++) {
            PddlStep step = plan.steps().get(i);
            String where = "step " + (i + 1) + " " + step + ": ";
            Action a = domain.action(step.name());
            if (a == null) return new Report(false, i, where + "unknown action '" + step.name() + "'", false);
            if (a.parameters().size() != step.args().size()) {
                return new Report(false, i, where + "'" + a.name() + "' takes " + a.parameters().size() + " arguments", false);
            }
            Map<String, String> binding = new HashMap<>();
            for (int k = 0; k < a.parameters().size(); k++) {
                TypedName p = a.parameters().get(k);
                String arg = step.args().get(k);
                Integer id = universe.ids.get(arg);
                if (id == null) return new Report(false, i, where + "unknown object '" + arg + "'", false);
                if (!universe.isOf(id, p.types())) {
                    return new Report(false, i, where + "'" + arg + "' is not of type " + String.join("|", p.types()) + " for " + p.name(), false);
                }
                binding.put(p.name(), arg);
            }
            try {
                String failure = ev.explainFalse(a.precondition(), binding);
                if (failure != null) return new Report(false, i, where + "precondition not satisfied: " + failure, false);
                List<Formula.Atom> adds = new ArrayList<>();
                List<Formula.Atom> dels = new ArrayList<>();
                Map<String, Double> updates = new HashMap<>();
                ev.effects(a.effects(), binding, adds, dels, updates);
                state.removeAll(dels);
                state.addAll(adds);
                fluents.putAll(updates);
                ev.derive(domain, strata);
            } catch (NumericValues.Fault e) {
                return new Report(false, i, where + e.getMessage(), false);
            }
        }
        String goalFailure;
        try {
            goalFailure = ev.explainFalse(problem.goal(), Map.of());
        } catch (NumericValues.Fault e) {
            return new Report(false, -1, "goal: " + e.getMessage(), false);
        }
        if (goalFailure != null) return new Report(false, -1, "goal not satisfied at the end: " + goalFailure, false);
        return new Report(true, -1, "valid", true);
    }

    private static final class Evaluator {
        private final ObjectUniverse universe;
        private final Set<Formula.Atom> state;
        private final Map<String, Double> fluents;

        Evaluator(ObjectUniverse universe, Set<Formula.Atom> state, Map<String, Double> fluents) {
            this.universe = universe;
            this.state = state;
            this.fluents = fluents;
        }

        private double value(NumericExpr e, Map<String, String> b) {
            return NumericValues.evaluate(NumericValues.ground(e, b), f -> {
                String key = NumericValues.key(f.name(), f.args());
                Double v = fluents.get(key);
                if (v == null) throw new NumericValues.Fault("(" + key + ") has no value (the problem's :init does not give it one)");
                return v;
            });
        }

        private Formula.Atom ground(Formula.Atom a, Map<String, String> b) {
            List<String> args = new ArrayList<>(a.args().size());
            for (String t : a.args()) args.add(b.getOrDefault(t, t));
            return new Formula.Atom(a.predicate(), args);
        }

        private static void collect(Formula f, List<Formula.Atom> out) {
            if (f instanceof Formula.Atom a) out.add(a);
            else if (f instanceof Formula.Not n) collect(n.body(), out);
            else if (f instanceof Formula.And a) a.parts().forEach(p -> collect(p, out));
            else if (f instanceof Formula.Or o) o.parts().forEach(p -> collect(p, out));
            else if (f instanceof Formula.Imply i) {
                collect(i.condition(), out);
                collect(i.consequence(), out);
            } else if (f instanceof Formula.Forall q) collect(q.body(), out);
            else if (f instanceof Formula.Exists q) collect(q.body(), out);
        }

        /** Whether the formula holds (as {@link #explainFalse} without building descriptions). */
        boolean holds(Formula f, Map<String, String> b) {
            if (f instanceof Formula.Atom a) return state.contains(ground(a, b));
            if (f instanceof Formula.Equals e) return b.getOrDefault(e.left(), e.left()).equals(b.getOrDefault(e.right(), e.right()));
            if (f instanceof Formula.Not n) return !holds(n.body(), b);
            if (f instanceof Formula.And and) {
                for (Formula p : and.parts()) if (!holds(p, b)) return false;
                return true;
            }
            if (f instanceof Formula.Or or) {
                for (Formula p : or.parts()) if (holds(p, b)) return true;
                return false;
            }
            if (f instanceof Formula.Imply i) return !holds(i.condition(), b) || holds(i.consequence(), b);
            if (f instanceof Formula.Compare c) return c.holds(value(c.left(), b), value(c.right(), b));
            if (f instanceof Formula.Exists e) {
                // nested exists over a conjunction: bind one variable at a time and test each conjunct
                // as soon as its variables are bound, instead of enumerating every combination
                List<TypedName> vars = new ArrayList<>(e.variables());
                Formula body = e.body();
                while (body instanceof Formula.Exists inner) {
                    vars.addAll(inner.variables());
                    body = inner.body();
                }
                List<Formula> conjuncts = body instanceof Formula.And and ? and.parts() : List.of(body);
                List<java.util.Set<String>> free = new ArrayList<>();
                for (Formula c : conjuncts) free.add(freeVariables(c));
                return witness(vars, 0, conjuncts, free, new java.util.HashMap<>(b), new boolean[conjuncts.size()]);
            }
            Formula.Forall q = (Formula.Forall) f;
            for (Map<String, String> nb : new Normalizer(universe).bindings(q.variables(), b)) {
                if (!holds(q.body(), nb)) return false;
            }
            return true;
        }

        private boolean witness(List<TypedName> vars, int i, List<Formula> conjuncts, List<java.util.Set<String>> free,
                                Map<String, String> b, boolean[] checked) {
            // test the conjuncts whose variables are all bound now
            List<Integer> now = new ArrayList<>();
            for (int c = 0; c < conjuncts.size(); c++) {
                if (checked[c] || !b.keySet().containsAll(free.get(c)) && i < vars.size()) continue;
                if (!holds(conjuncts.get(c), b)) {
                    for (int k : now) checked[k] = false;
                    return false;
                }
                checked[c] = true;
                now.add(c);
            }
            boolean found = i == vars.size();
            if (!found) {
                TypedName v = vars.get(i);
                for (int o : universe.ofTypes(v.types())) {
                    b.put(v.name(), universe.names.get(o));
                    if (witness(vars, i + 1, conjuncts, free, b, checked)) {
                        found = true;
                        break;
                    }
                }
                b.remove(v.name());
            }
            for (int k : now) checked[k] = false;
            return found;
        }

        /** The variables a formula uses that it does not quantify itself. */
        private static java.util.Set<String> freeVariables(Formula f) {
            java.util.Set<String> out = new java.util.HashSet<>();
            if (f instanceof Formula.Atom a) {
                for (String t : a.args()) if (t.startsWith("?")) out.add(t);
            } else if (f instanceof Formula.Equals e) {
                if (e.left().startsWith("?")) out.add(e.left());
                if (e.right().startsWith("?")) out.add(e.right());
            } else if (f instanceof Formula.Not n) {
                out.addAll(freeVariables(n.body()));
            } else if (f instanceof Formula.And a) {
                a.parts().forEach(p -> out.addAll(freeVariables(p)));
            } else if (f instanceof Formula.Or o) {
                o.parts().forEach(p -> out.addAll(freeVariables(p)));
            } else if (f instanceof Formula.Imply i) {
                out.addAll(freeVariables(i.condition()));
                out.addAll(freeVariables(i.consequence()));
            } else if (f instanceof Formula.Compare c) {
                for (NumericExpr.Fluent fl : org.triad.planner.pddl.NumericParts.fluents(c)) {
                    for (String t : fl.args()) if (t.startsWith("?")) out.add(t);
                }
            } else {
                boolean universal = f instanceof Formula.Forall;
                List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
                out.addAll(freeVariables(universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body()));
                vars.forEach(v -> out.remove(v.name()));
            }
            return out;
        }

        /** Null when the formula holds, else a description of a false part. */
        String explainFalse(Formula f, Map<String, String> b) {
            if (f instanceof Formula.Atom a) {
                Formula.Atom g = ground(a, b);
                return state.contains(g) ? null : PddlWriter.atom(g) + " is false";
            }
            if (f instanceof Formula.Equals e) {
                String l = b.getOrDefault(e.left(), e.left());
                String r = b.getOrDefault(e.right(), e.right());
                return l.equals(r) ? null : "(= " + l + " " + r + ") is false";
            }
            if (f instanceof Formula.Not n) {
                if (n.body() instanceof Formula.Atom a) {
                    Formula.Atom g = ground(a, b);
                    return state.contains(g) ? PddlWriter.atom(g) + " is true" : null;
                }
                return explainFalse(n.body(), b) == null ? "(not " + PddlWriter.formula(n.body()) + ") is false" : null;
            }
            if (f instanceof Formula.And and) {
                for (Formula p : and.parts()) {
                    String r = explainFalse(p, b);
                    if (r != null) return r;
                }
                return null;
            }
            if (f instanceof Formula.Or or) {
                for (Formula p : or.parts()) if (explainFalse(p, b) == null) return null;
                return "no disjunct of " + PddlWriter.formula(f) + " holds";
            }
            if (f instanceof Formula.Imply i) {
                return explainFalse(i.condition(), b) != null ? null : explainFalse(i.consequence(), b);
            }
            if (f instanceof Formula.Compare c) {
                double l = value(c.left(), b);
                double r = value(c.right(), b);
                Formula ground = new Formula.Compare(c.op(), NumericValues.ground(c.left(), b), NumericValues.ground(c.right(), b));
                return c.holds(l, r) ? null : PddlWriter.formula(ground) + " is false (" + PddlWriter.number(l) + " " + c.op() + " "
                        + PddlWriter.number(r) + ")";
            }
            boolean universal = f instanceof Formula.Forall;
            List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
            Formula body = universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body();
            for (Map<String, String> nb : new Normalizer(universe).bindings(vars, b)) {
                String r = explainFalse(body, nb);
                if (universal && r != null) return r;
                if (!universal && r == null) return null;
            }
            return universal ? null : "no witness for " + PddlWriter.formula(f);
        }

        /**
         * Recomputes the derived atoms from the basic ones: stratum by stratum, every rule instance
         * over the typed objects, until nothing new holds.
         */
        void derive(Domain domain, Map<String, Integer> strata) {
            if (strata.isEmpty()) return;
            state.removeIf(a -> strata.containsKey(a.predicate()));
            int top = strata.values().stream().mapToInt(Integer::intValue).max().orElse(0);
            for (int s = 0; s <= top; s++) {
                // a stratum whose rules read no derived predicate of their own stratum needs one pass
                boolean recursive = false;
                for (org.triad.planner.pddl.Axiom x : domain.axioms()) {
                    if (strata.get(x.predicate()) != s) continue;
                    List<Formula.Atom> atoms = new ArrayList<>();
                    collect(x.body(), atoms);
                    for (Formula.Atom at : atoms) recursive |= Integer.valueOf(s).equals(strata.get(at.predicate()));
                }
                boolean changed = true;
                while (changed) {
                    changed = false;
                    for (org.triad.planner.pddl.Axiom x : domain.axioms()) {
                        if (strata.get(x.predicate()) != s) continue;
                        for (Map<String, String> b : new Normalizer(universe).bindings(x.parameters(), Map.of())) {
                            List<String> args = new ArrayList<>();
                            for (TypedName p : x.parameters()) args.add(b.get(p.name()));
                            Formula.Atom head = new Formula.Atom(x.predicate(), args);
                            if (state.contains(head) || !holds(x.body(), b)) continue;
                            state.add(head);
                            changed = recursive;
                        }
                    }
                }
            }
        }

        void effects(List<PddlEffect> effects, Map<String, String> b, List<Formula.Atom> adds, List<Formula.Atom> dels,
                     Map<String, Double> updates) {
            for (PddlEffect e : effects) {
                if (e instanceof PddlEffect.Add a) adds.add(ground(a.atom(), b));
                else if (e instanceof PddlEffect.Delete d) dels.add(ground(d.atom(), b));
                else if (e instanceof PddlEffect.Forall q) {
                    for (Map<String, String> nb : new Normalizer(universe).bindings(q.variables(), b)) effects(q.body(), nb, adds, dels, updates);
                } else if (e instanceof PddlEffect.When w) {
                    // the state is still the one before the action: all effects are collected before any applies
                    if (holds(w.condition(), b)) effects(w.body(), b, adds, dels, updates);
                } else if (e instanceof PddlEffect.Increase i) {
                    // an action cost: total-cost starts at 0 unless :init says otherwise; several costs of one action add up
                    double amount = value(i.amount() instanceof org.triad.planner.pddl.NumericTerm.Function f
                            ? new NumericExpr.Fluent(f.name(), f.args())
                            : new NumericExpr.Number(((org.triad.planner.pddl.NumericTerm.Constant) i.amount()).value()), b);
                    double before = updates.containsKey(i.function()) ? updates.get(i.function()) : fluents.getOrDefault(i.function(), 0.0);
                    updates.put(i.function(), NumericValues.checked(before + amount, "(increase (" + i.function() + ") " + PddlWriter.number(amount) + ")"));
                } else if (e instanceof PddlEffect.NumericEffect n) {
                    List<String> args = new ArrayList<>(n.target().args().size());
                    for (String t : n.target().args()) args.add(b.getOrDefault(t, t));
                    String key = NumericValues.key(n.target().name(), args);
                    double amount = value(n.value(), b);
                    Double current = fluents.get(key);
                    if (current == null && !n.kind().equals("assign")) {
                        throw new NumericValues.Fault("(" + n.kind() + " (" + key + ") ...): (" + key + ") has no value to " + n.kind());
                    }
                    if (updates.containsKey(key)) throw new NumericValues.Fault("two effects change (" + key + ") in one step");
                    updates.put(key, NumericValues.checked(n.apply(current == null ? 0 : current, amount),
                            "(" + n.kind() + " (" + key + ") " + PddlWriter.number(amount) + ")"));
                }
            }
        }
    }
}
