package org.triad.runtime.app;

import java.util.Optional;

/**
 * Implemented by a robot or world implementation that can say why its last action returned
 * {@code false} (a door closed, a corridor blocked, an item out of reach), so the reason reaches the
 * Status port instead of a bare "failed".
 */
public interface FailureExplaining {
	/** Why the most recent action of this actor failed, or empty if it did not fail or nobody knows. */
	Optional<String> lastFailure();

	/** {@link #lastFailure()} with its cause; a fault unless the implementation knows better (traffic control's congestion). */
	default Optional<Failure> lastFailureWithCause() {
		return lastFailure().map(Failure::fault);
	}
}
