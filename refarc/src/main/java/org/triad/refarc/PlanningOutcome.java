package org.triad.refarc;

import org.triad.runtime.app.Plan;

/** What a {@link GoalPlanner} produced: a plan, or a failure with a reason. */
public sealed interface PlanningOutcome {
    static PlanningOutcome planned(Plan plan) {
        return new Planned(plan);
    }

    /** A failure that planning again may overcome: a timeout, a spent budget, a fault, a refuted plan. */
    static PlanningOutcome failed(String reason) {
        return new Failed(reason, false);
    }

    /**
     * A failure the planner proved: no plan reaches the goal from the state it planned from. Planning again from
     * an unchanged state gives the same answer, so the Controller aborts at once (unless an action failed since the
     * goal started: the world may have changed under it).
     */
    static PlanningOutcome unsolvable(String reason) {
        return new Failed(reason, true);
    }

    record Planned(Plan plan) implements PlanningOutcome {
        public Planned {
            if (plan == null) {
                throw new IllegalArgumentException("a planning success needs a plan");
            }
        }
    }

    /** A failure with its reason; {@code proven} when the planner proved the goal unreachable (see {@link #unsolvable}). */
    record Failed(String reason, boolean proven) implements PlanningOutcome {
        public Failed(String reason) {
            this(reason, false);
        }

        public Failed {
            if (reason == null || reason.isBlank()) {
                throw new IllegalArgumentException("a planning failure needs a reason");
            }
        }
    }
}
