package org.triad.refarc;

import java.util.List;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;

/** The result of {@link RefArcRunner#run}: how the task ended, every status event, and faults nobody handled. */
public record RefArcRun(TaskInstance task, Outcome outcome, List<Status> statuses, List<ComponentFault> unhandledFaults) {
    public enum Outcome { COMPLETED, ABORTED }

    public RefArcRun {
        statuses = List.copyOf(statuses);
        unhandledFaults = List.copyOf(unhandledFaults);
    }

    /** The status events as text, one per step. */
    public List<String> log() {
        return statuses.stream().map(Status::toString).toList();
    }
}
