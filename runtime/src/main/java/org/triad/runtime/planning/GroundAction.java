package org.triad.runtime.planning;

import java.util.List;

/** One step of a plan: an action name with object arguments, lower case. */
public record GroundAction(String name, List<String> args) {
    public GroundAction {
        args = List.copyOf(args);
    }

    public static GroundAction of(String name, String... args) {
        return new GroundAction(name, List.of(args));
    }

    /** {@code (move wp0 wp1)}, the form VAL and most planners read. */
    @Override
    public String toString() {
        return args.isEmpty() ? "(" + name + ")" : "(" + name + " " + String.join(" ", args) + ")";
    }
}
