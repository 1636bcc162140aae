package org.triad.refarc;

import org.triad.runtime.app.Plan;

/** What a {@link GoalPlanner} produced: a plan, or a failure with a reason. */
public sealed interface PlanningOutcome {
    static PlanningOutcome planned(Plan plan) {
        return new Planned(plan);
    }

    static PlanningOutcome failed(String reason) {
        return new Failed(reason);
    }

    record Planned(Plan plan) implements PlanningOutcome {
        public Planned {
            if (plan == null) {
                throw new IllegalArgumentException("a planning success needs a plan");
            }
        }
    }

    record Failed(String reason) implements PlanningOutcome {
        public Failed {
            if (reason == null || reason.isBlank()) {
                throw new IllegalArgumentException("a planning failure needs a reason");
            }
        }
    }
}
