package org.triad.planner;

/** A domain/problem that parses but cannot be planned for (unknown object, type or predicate, unsupported feature). */
public class PlanningInputException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public PlanningInputException(String message) {
        super(message);
    }
}
