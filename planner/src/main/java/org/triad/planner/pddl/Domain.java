package org.triad.planner.pddl;

import java.util.List;

/**
 * A PDDL domain. {@code types} lists each declared type with its parent(s) (undeclared parents
 * default to {@code object}); {@code functions} are only carried for action costs; {@code axioms}
 * are the rules of derived predicates.
 */
public record Domain(String name, List<String> requirements, List<TypedName> types, List<TypedName> constants,
                     List<PredicateDecl> predicates, List<PredicateDecl> functions, List<Action> actions, List<Axiom> axioms) {
    public Domain {
        requirements = List.copyOf(requirements);
        types = List.copyOf(types);
        constants = List.copyOf(constants);
        predicates = List.copyOf(predicates);
        functions = List.copyOf(functions);
        actions = List.copyOf(actions);
        axioms = List.copyOf(axioms);
    }

    /** A domain without derived predicates. */
    public Domain(String name, List<String> requirements, List<TypedName> types, List<TypedName> constants,
                  List<PredicateDecl> predicates, List<PredicateDecl> functions, List<Action> actions) {
        this(name, requirements, types, constants, predicates, functions, actions, List.of());
    }

    public Action action(String actionName) {
        for (Action a : actions) if (a.name().equals(actionName)) return a;
        return null;
    }
}
