package org.triad.planner.pddl;

import java.util.List;

/** An action effect: literals, {@code forall}, conditional ({@code when}) effects and {@code increase (total-cost)}. */
public sealed interface PddlEffect permits PddlEffect.Add, PddlEffect.Delete, PddlEffect.Forall, PddlEffect.When, PddlEffect.Increase {

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
}
