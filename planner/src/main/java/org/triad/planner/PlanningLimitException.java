package org.triad.planner;

/**
 * A task too large for the memory given, refused before it is instantiated: the message names the
 * phase and the size, e.g. {@code grounding would create 1·10⁹ actions of 'visit' (...)}.
 */
public class PlanningLimitException extends PlanningInputException {
    private static final long serialVersionUID = 1L;

    public PlanningLimitException(String message) {
        super(message);
    }
}
