package org.triad.planner;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.triad.planner.pddl.Axiom;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;

/**
 * The strata of a domain's derived predicates: a rule's predicate sits at least as high as every
 * derived predicate its body uses positively and above every one it uses negatively, so evaluating
 * the strata bottom-up gives negation its meaning (PDDL 2.2's stratified semantics).
 */
final class DerivedStrata {
    private DerivedStrata() { }

    /** Stratum per derived predicate; a domain whose negation runs through recursion is an input error. */
    static Map<String, Integer> of(Domain d) {
        Map<String, Integer> level = new HashMap<>();
        for (Axiom a : d.axioms()) level.put(a.predicate(), 0);
        int limit = level.size() + 1;
        boolean changed = true;
        while (changed) {
            changed = false;
            for (Axiom a : d.axioms()) {
                int need = need(a.body(), false, level);
                if (need > level.get(a.predicate())) {
                    if (need > limit) {
                        throw new PlanningInputException("derived predicate '" + a.predicate()
                                + "' depends on its own negation: the rules are not stratified");
                    }
                    level.put(a.predicate(), need);
                    changed = true;
                }
            }
        }
        return level;
    }

    private static int need(Formula f, boolean negated, Map<String, Integer> level) {
        if (f instanceof Formula.Atom a) {
            Integer l = level.get(a.predicate());
            return l == null ? 0 : l + (negated ? 1 : 0);
        }
        if (f instanceof Formula.Not n) return need(n.body(), !negated, level);
        if (f instanceof Formula.Imply i) return Math.max(need(i.condition(), !negated, level), need(i.consequence(), negated, level));
        List<Formula> parts = f instanceof Formula.And a ? a.parts() : f instanceof Formula.Or o ? o.parts()
                : f instanceof Formula.Forall q ? List.of(q.body()) : f instanceof Formula.Exists q ? List.of(q.body()) : List.of();
        int m = 0;
        for (Formula p : parts) m = Math.max(m, need(p, negated, level));
        return m;
    }
}
