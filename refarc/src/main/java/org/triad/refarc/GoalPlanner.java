package org.triad.refarc;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;

/** The application-specific planner back-end (generated: goal, actor and domain models to PDDL). */
@FunctionalInterface
public interface GoalPlanner {
    /** Plans {@code goal} from {@code from}; may take long. Never null; a failure carries a reason. */
    PlanningOutcome plan(GoalInstance goal, State from) throws Exception;

    /**
     * Plans {@code goal} so that the goals {@code then} (the rest of its task) stay reachable from where the
     * plan ends; a back-end that cannot look ahead plans the goal on its own.
     */
    default PlanningOutcome plan(GoalInstance goal, java.util.List<GoalInstance> then, State from) throws Exception {
        return plan(goal, from);
    }
}
