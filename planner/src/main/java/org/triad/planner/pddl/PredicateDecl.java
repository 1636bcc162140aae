package org.triad.planner.pddl;

import java.util.List;

public record PredicateDecl(String name, List<TypedName> parameters) {
    public PredicateDecl { parameters = List.copyOf(parameters); }
}
