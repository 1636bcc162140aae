package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.NumericTerm;
import org.triad.planner.pddl.TypedName;

/**
 * Rewrites formulas into disjunctive normal form over literals, expanding quantifiers over the
 * (finite) objects of their types, and flattens quantified effects. Only action parameters stay as
 * variables.
 */
final class Normalizer {
    /** Limit on DNF size: beyond it the domain needs a smarter compilation than we do. */
    static final int MAX_DISJUNCTS = 4096;

    /** A literal: an atom or an equality ({@code atom == null}), positive or negated. */
    record Lit(Formula.Atom atom, String left, String right, boolean positive) { }

    /** A literal effect after quantifier expansion. */
    record EffectLit(Formula.Atom atom, boolean add) { }

    /**
     * A conditional effect after quantifier expansion: the condition and literals still mention the
     * action parameters (and nothing else free); grounding decides per operator whether it stays conditional.
     */
    record CondEffect(Formula condition, List<EffectLit> effects) { }

    private final ObjectUniverse universe;
    private final int maxDisjuncts;

    Normalizer(ObjectUniverse universe) {
        this(universe, MAX_DISJUNCTS);
    }

    /** {@code maxDisjuncts}: beyond it {@link #dnf} throws {@link PlanningInputException}. */
    Normalizer(ObjectUniverse universe, int maxDisjuncts) {
        this.universe = universe;
        this.maxDisjuncts = maxDisjuncts;
    }

    List<List<Lit>> dnf(Formula f) {
        return dnf(f, Map.of(), false);
    }

    private List<List<Lit>> dnf(Formula f, Map<String, String> subst, boolean negated) {
        if (f instanceof Formula.Atom a) {
            List<String> args = new ArrayList<>(a.args().size());
            for (String t : a.args()) args.add(subst.getOrDefault(t, t));
            return single(new Lit(new Formula.Atom(a.predicate(), args), null, null, !negated));
        }
        if (f instanceof Formula.Equals e) {
            return single(new Lit(null, subst.getOrDefault(e.left(), e.left()), subst.getOrDefault(e.right(), e.right()), !negated));
        }
        if (f instanceof Formula.Not n) return dnf(n.body(), subst, !negated);
        if (f instanceof Formula.Imply i) {
            return dnf(new Formula.Or(List.of(new Formula.Not(i.condition()), i.consequence())), subst, negated);
        }
        if (f instanceof Formula.And a) {
            return negated ? union(a.parts(), subst, true) : product(a.parts(), subst, false);
        }
        if (f instanceof Formula.Or o) {
            return negated ? product(o.parts(), subst, true) : union(o.parts(), subst, false);
        }
        boolean universal = f instanceof Formula.Forall;
        List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
        Formula body = universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body();
        List<Map<String, String>> bindings = bindings(vars, subst);
        List<List<Lit>> out = null;
        boolean conjunctive = universal != negated;
        for (Map<String, String> b : bindings) {
            List<List<Lit>> d = dnf(body, b, negated);
            out = out == null ? d : conjunctive ? cross(out, d) : concat(out, d);
        }
        if (out == null) return conjunctive ? single() : List.of();
        return out;
    }

    List<Map<String, String>> bindings(List<TypedName> vars, Map<String, String> base) {
        checkBindings(universe, vars);
        GroundingLimits.Clock clock = GroundingLimits.clock();
        List<Map<String, String>> out = new ArrayList<>();
        out.add(new HashMap<>(base));
        for (TypedName v : vars) {
            int[] objs = universe.ofTypes(v.types());
            List<Map<String, String>> next = new ArrayList<>();
            for (Map<String, String> m : out) {
                for (int o : objs) {
                    clock.tick();
                    Map<String, String> n = new HashMap<>(m);
                    n.put(v.name(), universe.names.get(o));
                    next.add(n);
                }
            }
            out = next;
        }
        return out;
    }

    private static List<List<Lit>> single(Lit... lits) {
        List<List<Lit>> out = new ArrayList<>();
        out.add(new ArrayList<>(List.of(lits)));
        return out;
    }

    private List<List<Lit>> product(List<Formula> parts, Map<String, String> subst, boolean negated) {
        List<List<Lit>> acc = single();
        for (Formula p : parts) acc = cross(acc, dnf(p, subst, negated));
        return acc;
    }

    private List<List<Lit>> union(List<Formula> parts, Map<String, String> subst, boolean negated) {
        List<List<Lit>> acc = new ArrayList<>();
        for (Formula p : parts) acc = concat(acc, dnf(p, subst, negated));
        return acc;
    }

    private List<List<Lit>> cross(List<List<Lit>> a, List<List<Lit>> b) {
        if ((long) a.size() * b.size() > maxDisjuncts) {
            throw new PlanningInputException("formula too large in disjunctive normal form (> " + maxDisjuncts + " disjuncts)");
        }
        List<List<Lit>> out = new ArrayList<>(a.size() * b.size());
        for (List<Lit> x : a) {
            for (List<Lit> y : b) {
                List<Lit> c = new ArrayList<>(x.size() + y.size());
                c.addAll(x);
                c.addAll(y);
                out.add(c);
            }
        }
        return out;
    }

    private List<List<Lit>> concat(List<List<Lit>> a, List<List<Lit>> b) {
        if (a.size() + b.size() > maxDisjuncts) {
            throw new PlanningInputException("formula too large in disjunctive normal form (> " + maxDisjuncts + " disjuncts)");
        }
        List<List<Lit>> out = new ArrayList<>(a);
        out.addAll(b);
        return out;
    }

    /**
     * Literal effects with {@code forall} expanded; {@code costs} receives the {@code increase}
     * amounts, {@code conditional} the {@code when} effects (a nested {@code when} conjoins its condition).
     */
    void effects(List<PddlEffect> effects, Map<String, String> subst, List<EffectLit> out, List<NumericTerm> costs,
                 List<CondEffect> conditional) {
        effects(effects, subst, null, out, costs, conditional);
    }

    private void effects(List<PddlEffect> effects, Map<String, String> subst, Formula condition, List<EffectLit> out,
                         List<NumericTerm> costs, List<CondEffect> conditional) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.When w) {
                Formula c = substitute(w.condition(), subst);
                Formula all = condition == null ? c : new Formula.And(List.of(condition, c));
                List<EffectLit> body = new ArrayList<>();
                effects(w.body(), subst, all, body, costs, conditional);
                if (!body.isEmpty()) conditional.add(new CondEffect(all, body));
                continue;
            }
            if (e instanceof PddlEffect.Add a) {
                out.add(new EffectLit(substitute(a.atom(), subst), true));
            } else if (e instanceof PddlEffect.Delete d) {
                out.add(new EffectLit(substitute(d.atom(), subst), false));
            } else if (e instanceof PddlEffect.Forall q) {
                for (Map<String, String> b : bindings(q.variables(), subst)) effects(q.body(), b, condition, out, costs, conditional);
            } else if (e instanceof PddlEffect.Increase i) {
                if (!i.function().equals("total-cost")) {
                    throw new PlanningInputException("only (increase (total-cost) ...) is supported, found function '" + i.function() + "'");
                }
                NumericTerm amount = i.amount();
                if (amount instanceof NumericTerm.Function fn && !subst.isEmpty()) {
                    List<String> args = new ArrayList<>();
                    for (String t : fn.args()) args.add(subst.getOrDefault(t, t));
                    amount = new NumericTerm.Function(fn.name(), args);
                }
                costs.add(amount);
            }
        }
    }

    /** The formula with its free variables replaced (a quantifier's own variables shadow {@code subst}). */
    static Formula substitute(Formula f, Map<String, String> subst) {
        if (subst.isEmpty()) return f;
        if (f instanceof Formula.Atom a) return substitute(a, subst);
        if (f instanceof Formula.Equals e) return new Formula.Equals(subst.getOrDefault(e.left(), e.left()), subst.getOrDefault(e.right(), e.right()));
        if (f instanceof Formula.Not n) return new Formula.Not(substitute(n.body(), subst));
        if (f instanceof Formula.And a) return new Formula.And(a.parts().stream().map(p -> substitute(p, subst)).toList());
        if (f instanceof Formula.Or o) return new Formula.Or(o.parts().stream().map(p -> substitute(p, subst)).toList());
        if (f instanceof Formula.Imply i) return new Formula.Imply(substitute(i.condition(), subst), substitute(i.consequence(), subst));
        boolean universal = f instanceof Formula.Forall;
        List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
        Formula body = universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body();
        Map<String, String> inner = new HashMap<>(subst);
        vars.forEach(v -> inner.remove(v.name()));
        Formula b = substitute(body, inner);
        return universal ? new Formula.Forall(vars, b) : new Formula.Exists(vars, b);
    }

    private static Formula.Atom substitute(Formula.Atom a, Map<String, String> subst) {
        if (subst.isEmpty()) return a;
        List<String> args = new ArrayList<>(a.args().size());
        for (String t : a.args()) args.add(subst.getOrDefault(t, t));
        return new Formula.Atom(a.predicate(), args);
    }

    /** Refuses a quantifier whose bindings the memory cannot hold (forall ?x ?y ?z over thousands of objects). */
    static void checkBindings(ObjectUniverse universe, List<TypedName> vars) {
        int[] sizes = new int[vars.size()];
        for (int i = 0; i < sizes.length; i++) sizes[i] = universe.ofTypes(vars.get(i).types()).length;
        StringBuilder names = new StringBuilder();
        for (TypedName v : vars) names.append(names.length() == 0 ? "" : " ").append(v.name());
        GroundingLimits.check("bindings of the quantifier over " + names, GroundingLimits.log10Combinations(sizes), GroundingLimits.maxBindings(),
                vars.size() + " variable" + (vars.size() == 1 ? "" : "s") + " over " + GroundingLimits.objects(sizes));
    }
}
