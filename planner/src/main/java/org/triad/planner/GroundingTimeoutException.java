package org.triad.planner;

/** The timeout passed while grounding ({@link GroundingLimits.Clock#tick()}); the engine answers TIMEOUT. */
final class GroundingTimeoutException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    GroundingTimeoutException() {
        super("time limit reached while grounding", null, false, false);
    }
}
