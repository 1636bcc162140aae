package org.triad.runtime.pddl;

import java.util.List;

/** An action effect: literals, unconditional {@code forall} and {@code increase (total-cost)}. */
public sealed interface Effect permits Effect.Add, Effect.Delete, Effect.Forall, Effect.Increase {

    record Add(Formula.Atom atom) implements Effect { }

    record Delete(Formula.Atom atom) implements Effect { }

    record Forall(List<TypedName> variables, List<Effect> body) implements Effect {
        public Forall {
            variables = List.copyOf(variables);
            body = List.copyOf(body);
        }
    }

    /**
     * {@code (increase (total-cost) X)}: {@code amount} is a number or a function term such as
     * {@code (travel-slow ?f1 ?f2)}; kept as a term so it can be evaluated against the problem.
     */
    record Increase(String function, NumericTerm amount) implements Effect { }
}
