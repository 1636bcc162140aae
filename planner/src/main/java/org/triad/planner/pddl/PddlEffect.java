package org.triad.planner.pddl;

import java.util.List;

/** An action effect: literals, {@code forall}, conditional ({@code when}) effects and {@code increase (total-cost)}. */
public sealed interface PddlEffect permits PddlEffect.Add, PddlEffect.Delete, PddlEffect.Forall, PddlEffect.When, PddlEffect.Increase,
        PddlEffect.NumericEffect {

    record Add(Formula.Atom atom) implements PddlEffect { }

    record Delete(Formula.Atom atom) implements PddlEffect { }

    record Forall(List<TypedName> variables, List<PddlEffect> body) implements PddlEffect {
        public Forall {
            variables = List.copyOf(variables);
            body = List.copyOf(body);
        }
    }

    /** {@code (when CONDITION EFFECT)}: the body applies only if the condition holds in the state before the action. */
    record When(Formula condition, List<PddlEffect> body) implements PddlEffect {
        public When { body = List.copyOf(body); }
    }

    /**
     * {@code (increase (total-cost) X)}: {@code amount} is a number or a function term such as
     * {@code (travel-slow ?f1 ?f2)}; kept as a term so it can be evaluated against the problem.
     */
    record Increase(String function, NumericTerm amount) implements PddlEffect { }

    /**
     * A numeric effect of PDDL 2.1 on a fluent other than a constant action cost: {@code (assign f v)},
     * {@code (increase f v)}, {@code (decrease f v)}, {@code (scale-up f v)}, {@code (scale-down f v)};
     * {@code value} is read in the state before the action.
     */
    record NumericEffect(String kind, NumericExpr.Fluent target, NumericExpr value) implements PddlEffect {
        public static final List<String> KINDS = List.of("assign", "increase", "decrease", "scale-up", "scale-down");

        public NumericEffect {
            if (!KINDS.contains(kind)) throw new IllegalArgumentException("not a numeric effect: " + kind);
        }

        /** The fluent's new value from its value before the action and the value of {@code value} there. */
        public double apply(double current, double amount) {
            return switch (kind) {
                case "assign" -> amount;
                case "increase" -> current + amount;
                case "decrease" -> current - amount;
                case "scale-up" -> current * amount;
                default -> current / amount;
            };
        }
    }
}
