package org.triad.refarc;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;

/**
 * Planner to Controller (possibly through extensions such as {@link PlanVerifier}): the outcome of
 * planning {@code goal} from {@code from}, or the news that the goal already held in {@code from}.
 */
public record PlanResult(long requestId, GoalInstance goal, State from, PlanningOutcome outcome, boolean alreadySatisfied)
        implements Correlated {

    public static PlanResult of(PlanRequest request, State from, PlanningOutcome outcome) {
        return new PlanResult(request.requestId(), request.goal(), from, outcome, false);
    }

    public static PlanResult alreadySatisfied(PlanRequest request, State from) {
        return new PlanResult(request.requestId(), request.goal(), from, PlanningOutcome.planned(new Plan(java.util.List.of())), true);
    }

    /** The same request answered with another outcome, e.g. a refuted plan turned into a failure. */
    public PlanResult withOutcome(PlanningOutcome other) {
        return new PlanResult(requestId, goal, from, other, false);
    }

    @Override
    public String toString() {
        String what = alreadySatisfied ? "already satisfied"
                : outcome instanceof PlanningOutcome.Planned p ? p.plan().size() + (p.plan().size() == 1 ? " action" : " actions")
                : "failed: " + ((PlanningOutcome.Failed) outcome).reason();
        return "plan result #" + requestId + " for " + goal.describe() + ": " + what;
    }
}
