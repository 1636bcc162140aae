package org.triad.planner.pddl;

import java.util.List;

/**
 * A derived predicate's rule, {@code (:derived (PREDICATE PARAMETERS) BODY)}: the atom holds in a
 * state exactly when some rule for it makes it true (least fixpoint, negation stratified).
 */
public record Axiom(String predicate, List<TypedName> parameters, Formula body) {
    public Axiom {
        parameters = List.copyOf(parameters);
    }
}
