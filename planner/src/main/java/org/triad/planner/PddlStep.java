package org.triad.planner;

import java.util.List;

/** One step of a plan: an action name with object arguments, lower case. */
public record PddlStep(String name, List<String> args) {
    public PddlStep {
        args = List.copyOf(args);
    }

    public static PddlStep of(String name, String... args) {
        return new PddlStep(name, List.of(args));
    }

    /** {@code (move wp0 wp1)}, the form VAL and most planners read. */
    @Override
    public String toString() {
        return args.isEmpty() ? "(" + name + ")" : "(" + name + " " + String.join(" ", args) + ")";
    }
}
