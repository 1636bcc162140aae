package org.triad.refarc;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;

/** The application-specific planner back-end (generated: goal, actor and domain models to PDDL). */
@FunctionalInterface
public interface GoalPlanner {
    /** Plans {@code goal} from {@code from}; may take long. Never null; a failure carries a reason. */
    PlanningOutcome plan(GoalInstance goal, State from) throws Exception;
}
