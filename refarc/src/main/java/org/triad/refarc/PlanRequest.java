package org.triad.refarc;

import java.util.List;

import org.triad.runtime.app.GoalInstance;

/**
 * Controller to Planner: plan this goal from the current state, keeping the goals {@code then} (the rest of
 * its task, in order) reachable from where the plan ends, so that a task does not strand its robot.
 */
public record PlanRequest(long requestId, GoalInstance goal, List<GoalInstance> then) implements Correlated {
    public PlanRequest {
        then = List.copyOf(then);
    }

    /** A goal planned on its own. */
    public PlanRequest(long requestId, GoalInstance goal) {
        this(requestId, goal, List.of());
    }

    @Override
    public String toString() {
        return "plan request #" + requestId + " for " + goal.describe();
    }
}
