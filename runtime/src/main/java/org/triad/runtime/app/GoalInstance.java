package org.triad.runtime.app;

import java.util.List;

/** A goal with its parameters bound: a situation that must hold. */
public interface GoalInstance {
    /** The goal model's name, e.g. {@code IsAt}. */
    String name();

    /** The arguments bound to the goal's parameters, in order. */
    List<Object> args();

    /** Whether the goal's situation holds in the given state. */
    boolean isSatisfiedIn(State state);

    /** A readable form such as {@code IsAt(ward3)}. */
    default String describe() {
        StringBuilder b = new StringBuilder(name()).append('(');
        for (int i = 0; i < args().size(); i++) {
            if (i > 0) {
                b.append(", ");
            }
            b.append(args().get(i));
        }
        return b.append(')').toString();
    }
}
