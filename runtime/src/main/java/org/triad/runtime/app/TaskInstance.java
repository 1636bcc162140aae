package org.triad.runtime.app;

import java.util.List;

/** A task with its parameters substituted into its goals: the goals to satisfy in order. */
public interface TaskInstance {
    /** The task model's name, e.g. {@code Fetch}. */
    String name();

    /** The arguments bound to the task's parameters, in order. */
    List<Object> args();

    /** The instantiated goal sequence. */
    List<GoalInstance> goals();

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
