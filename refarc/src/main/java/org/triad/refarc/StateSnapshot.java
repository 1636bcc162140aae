package org.triad.refarc;

import org.triad.runtime.app.State;

/** From StateProvider: the state fetched for request {@code requestId}. */
public record StateSnapshot(long requestId, State state) implements Correlated {
    @Override
    public String toString() {
        return "state #" + requestId;
    }
}
