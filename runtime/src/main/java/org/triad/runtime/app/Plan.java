package org.triad.runtime.app;

import java.util.List;

/** A sequence of actions that achieves a goal from the state it was planned from. */
public record Plan(List<GroundAction> actions) {
    public Plan {
        actions = List.copyOf(actions);
    }

    public int size() {
        return actions.size();
    }

    public boolean isEmpty() {
        return actions.isEmpty();
    }
}
