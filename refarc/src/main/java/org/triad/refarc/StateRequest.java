package org.triad.refarc;

/** To StateProvider: fetch the current state for request {@code requestId}. */
public record StateRequest(long requestId) implements Correlated {
    @Override
    public String toString() {
        return "state request #" + requestId;
    }
}
