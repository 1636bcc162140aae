package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.TypedName;

/**
 * Grounds an ADL formula (quantifiers, {@code or}, {@code imply}, {@code not} over any formula,
 * equality) for one binding of the action parameters: quantifiers are expanded over the objects of
 * their types, static atoms and equalities are evaluated at once, so only fluent facts remain, and
 * the result is put in disjunctive normal form over fact ids. Evaluating the static parts before
 * the normal form is what keeps it small: {@code (forall (?p) (imply (vip ?p) (served ?p)))} is a
 * conjunction over the few VIPs, not a disjunction over all passengers.
 */
final class GroundFormula {
    /** A disjunct: fluent facts that must be true ({@code pos}) and false ({@code neg}), sorted. */
    record Conj(int[] pos, int[] neg) { }

    private final Grounder g;
    /** For goals: a fluent atom without a fact id was never reached, so its negation holds without creating one. */
    private final boolean existingNegativesOnly;

    GroundFormula(Grounder grounder, boolean existingNegativesOnly) {
        this.g = grounder;
        this.existingNegativesOnly = existingNegativesOnly;
    }

    /** The disjuncts of the formula under {@code binding}: empty if it never holds, one empty conjunction if it always does. */
    List<Conj> dnf(Formula f, Map<String, String> binding) {
        Node n = simplify(f, binding, false);
        List<Set<Integer>> raw = dnf(n);
        List<Conj> out = new ArrayList<>(raw.size());
        Set<Set<Integer>> seen = new HashSet<>();
        for (Set<Integer> c : raw) {
            if (!seen.add(c)) continue;
            List<Integer> pos = new ArrayList<>();
            List<Integer> neg = new ArrayList<>();
            for (int l : c) (l >= 0 ? pos : neg).add(l >= 0 ? l : ~l);
            out.add(new Conj(Grounder.sortedUnique(pos), Grounder.sortedUnique(neg)));
        }
        return out;
    }

    // ---- simplified ground formulas in negation normal form -------------------------------------

    private sealed interface Node permits Const, Lit, And, Or { }

    private record Const(boolean value) implements Node { }

    /** {@code code} is a fact id, or {@code ~id} for its negation. */
    private record Lit(int code) implements Node { }

    private record And(List<Node> parts) implements Node { }

    private record Or(List<Node> parts) implements Node { }

    private static final Const TRUE = new Const(true);
    private static final Const FALSE = new Const(false);

    private Node simplify(Formula f, Map<String, String> b, boolean negated) {
        if (f instanceof Formula.Atom a) {
            int p = g.pred(a);
            int[] args = new int[a.args().size()];
            for (int i = 0; i < args.length; i++) args[i] = g.universe.id(b.getOrDefault(a.args().get(i), a.args().get(i)));
            if (!g.fluent[p]) return g.isStaticTrue(p, args) != negated ? TRUE : FALSE;
            if (negated && existingNegativesOnly) {
                Integer id = g.existingFactId(p, args);
                return id == null ? TRUE : new Lit(~id);
            }
            int id = g.factId(p, args);
            return new Lit(negated ? ~id : id);
        }
        if (f instanceof Formula.Equals e) {
            boolean same = g.universe.id(b.getOrDefault(e.left(), e.left())) == g.universe.id(b.getOrDefault(e.right(), e.right()));
            return same != negated ? TRUE : FALSE;
        }
        if (f instanceof Formula.Not n) return simplify(n.body(), b, !negated);
        if (f instanceof Formula.Imply i) {
            return simplify(new Formula.Or(List.of(new Formula.Not(i.condition()), i.consequence())), b, negated);
        }
        if (f instanceof Formula.And a) return junction(a.parts(), b, negated, !negated);
        if (f instanceof Formula.Or o) return junction(o.parts(), b, negated, negated);
        boolean universal = f instanceof Formula.Forall;
        List<TypedName> vars = universal ? ((Formula.Forall) f).variables() : ((Formula.Exists) f).variables();
        Formula body = universal ? ((Formula.Forall) f).body() : ((Formula.Exists) f).body();
        boolean conjunctive = universal != negated;
        List<Node> parts = new ArrayList<>();
        for (Map<String, String> nb : bindings(vars, b)) {
            Node n = simplify(body, nb, negated);
            if (n instanceof Const c) {
                if (c.value() != conjunctive) return c;
                continue;
            }
            parts.add(n);
        }
        return combine(parts, conjunctive);
    }

    private Node junction(List<Formula> fs, Map<String, String> b, boolean negated, boolean conjunctive) {
        List<Node> parts = new ArrayList<>();
        for (Formula f : fs) {
            Node n = simplify(f, b, negated);
            if (n instanceof Const c) {
                if (c.value() != conjunctive) return c; // a false conjunct or a true disjunct decides
                continue;
            }
            parts.add(n);
        }
        return combine(parts, conjunctive);
    }

    private static Node combine(List<Node> parts, boolean conjunctive) {
        if (parts.isEmpty()) return conjunctive ? TRUE : FALSE;
        if (parts.size() == 1) return parts.get(0);
        return conjunctive ? new And(parts) : new Or(parts);
    }

    private List<Map<String, String>> bindings(List<TypedName> vars, Map<String, String> base) {
        Normalizer.checkBindings(g.universe, vars);
        GroundingLimits.Clock clock = GroundingLimits.clock();
        List<Map<String, String>> out = new ArrayList<>();
        out.add(base);
        for (TypedName v : vars) {
            List<Map<String, String>> next = new ArrayList<>();
            for (Map<String, String> m : out) {
                for (int o : g.universe.ofTypes(v.types())) {
                    clock.tick();
                    Map<String, String> n = new HashMap<>(m);
                    n.put(v.name(), g.universe.names.get(o));
                    next.add(n);
                }
            }
            out = next;
        }
        return out;
    }

    // ---- normal form ---------------------------------------------------------------------------

    /** Disjuncts as sets of literal codes; contradictory ones are dropped. */
    private List<Set<Integer>> dnf(Node n) {
        if (n instanceof Const c) {
            List<Set<Integer>> out = new ArrayList<>();
            if (c.value()) out.add(new HashSet<>());
            return out;
        }
        if (n instanceof Lit l) {
            List<Set<Integer>> out = new ArrayList<>();
            Set<Integer> s = new HashSet<>();
            s.add(l.code());
            out.add(s);
            return out;
        }
        if (n instanceof Or o) {
            List<Set<Integer>> out = new ArrayList<>();
            for (Node p : o.parts()) {
                out.addAll(dnf(p));
                check(out.size());
            }
            return out;
        }
        List<Set<Integer>> acc = new ArrayList<>();
        acc.add(new HashSet<>());
        for (Node p : ((And) n).parts()) {
            List<Set<Integer>> d = dnf(p);
            List<Set<Integer>> next = new ArrayList<>();
            for (Set<Integer> x : acc) {
                for (Set<Integer> y : d) {
                    Set<Integer> c = new HashSet<>(x);
                    boolean consistent = true;
                    for (int l : y) {
                        if (c.contains(~l)) {
                            consistent = false;
                            break;
                        }
                        c.add(l);
                    }
                    if (consistent) next.add(c);
                }
                check(next.size());
            }
            acc = next;
            if (acc.isEmpty()) break;
        }
        return acc;
    }

    private static void check(int size) {
        if (size > Normalizer.MAX_DISJUNCTS) {
            throw new PlanningInputException("formula too large in disjunctive normal form after grounding (> "
                    + Normalizer.MAX_DISJUNCTS + " disjuncts)");
        }
    }
}
