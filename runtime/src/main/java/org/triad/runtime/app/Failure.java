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
		CONGESTION,
		/**
		 * A refusal the planner proved: from the state the robot and the building reported, no plan reaches the goal
		 * (a battery too low for the trip, an item nowhere to be found). Not the robot's fault: any robot in that state
		 * gets the same answer, and nothing was tried; someone changes the state (charges the robot, brings the item) or
		 * the task.
		 */
		REFUSED
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
