package org.triad.runtime.app;

import java.util.List;
import java.util.stream.Collectors;

/**
 * An action of an actor with its arguments bound: one step of a plan.
 *
 * @param actor  the name of the actor (robot or world) that owns the action
 * @param action the action's name
 * @param args   the arguments, domain objects or literal values (Integer, Double, String, Boolean, enum constants)
 */
public record GroundAction(String actor, String action, List<Object> args) {
    public GroundAction {
        args = List.copyOf(args);
    }

    @Override
    public String toString() {
        return actor + "." + action + "(" + args.stream().map(String::valueOf).collect(Collectors.joining(", ")) + ")";
    }
}
