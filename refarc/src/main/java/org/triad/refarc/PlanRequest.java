package org.triad.refarc;

import org.triad.runtime.app.GoalInstance;

/** Controller to Planner: plan this goal from the current state. */
public record PlanRequest(long requestId, GoalInstance goal) implements Correlated {
    @Override
    public String toString() {
        return "plan request #" + requestId + " for " + goal.describe();
    }
}
