package org.triad.planner.pddl;

import java.util.List;

/** An action schema; {@code precondition} is an empty {@code and} when absent. */
public record Action(String name, List<TypedName> parameters, Formula precondition, List<PddlEffect> effects) {
    public Action {
        parameters = List.copyOf(parameters);
        effects = List.copyOf(effects);
    }
}
