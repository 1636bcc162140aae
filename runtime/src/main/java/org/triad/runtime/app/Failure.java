package org.triad.runtime.app;

import java.util.Objects;

/**
 * Why an action failed, with what kind of cause it is, so that the layers above (RefArc's abort, the fleet
 * service) decide on the cause instead of matching the reason's wording.
 */
public record Failure(String reason, Cause cause) {
	/** What kind of trouble a failure is. */
	public enum Cause {
		/** The robot's, a device's or the plan's trouble: an operator looks at it. */
		FAULT,
		/**
		 * The building's congestion: traffic control gave up on a drive (a wait for other robots beyond its bound, a
		 * drive refused to avoid a deadlock, a robot that made way for another). Not the robot's fault, and the same
		 * task may well succeed once the others have moved on.
		 */
		CONGESTION
	}

	public Failure {
		Objects.requireNonNull(reason, "reason");
		Objects.requireNonNull(cause, "cause");
	}

	public static Failure fault(String reason) {
		return new Failure(reason, Cause.FAULT);
	}

	public static Failure congestion(String reason) {
		return new Failure(reason, Cause.CONGESTION);
	}
}
