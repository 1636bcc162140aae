package org.triad.planner.pddl;

import java.util.List;

/**
 * A PDDL problem. {@code numericInit} holds {@code (= (f args) value)} facts (action costs);
 * {@code metric} is e.g. {@code "minimize (total-cost)"} or null.
 */
public record Problem(String name, String domainName, List<TypedName> objects, List<Formula.Atom> init,
                      List<NumericFact> numericInit, Formula goal, String metric) {
    public Problem {
        objects = List.copyOf(objects);
        init = List.copyOf(init);
        numericInit = List.copyOf(numericInit);
    }

    public record NumericFact(String function, List<String> args, double value) {
        public NumericFact { args = List.copyOf(args); }
    }

    /** A copy with another initial state and goal: the objects stay, as in successive goals of one task. */
    public Problem with(List<Formula.Atom> newInit, Formula newGoal) {
        return new Problem(name, domainName, objects, newInit, numericInit, newGoal, metric);
    }
}
