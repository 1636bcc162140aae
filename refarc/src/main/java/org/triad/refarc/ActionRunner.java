package org.triad.refarc;

import java.util.Optional;
import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/** The application-specific action back-end: the generated ActionExecutor behaviour calling {@code IRobot}/{@code IWorld}. */
public interface ActionRunner {
    /** A description of the precondition part of {@code action} that does not hold in {@code now}, or empty if it holds. */
    Optional<String> violatedPrecondition(GroundAction action, State now) throws Exception;

    /** Executes {@code action} on the platform; may take seconds. Returns whether it succeeded; throwing counts as failure. */
    boolean execute(GroundAction action) throws Exception;

    /** Why {@code action}, just executed, returned {@code false}, if the platform can tell; reported on Status. */
    default Optional<String> failureReason(GroundAction action) {
        return Optional.empty();
    }

    /**
     * {@link #failureReason} with its cause (a fault unless the platform says it was the building's congestion): the
     * abort carries it, and a fleet queues a task that congestion ended again instead of calling an operator.
     */
    default Optional<Failure> failure(GroundAction action) {
        return failureReason(action).map(Failure::fault);
    }
}
