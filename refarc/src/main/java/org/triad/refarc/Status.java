package org.triad.refarc;

import java.util.stream.Collectors;
import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;

/** What RefArc reports on its Status port, one event per step of task execution. */
public sealed interface Status {

    /** A task arrived while another runs; it waits its turn. */
    record TaskQueued(TaskInstance task, int waiting) implements Status {
        @Override
        public String toString() {
            return "task " + task.describe() + " queued (" + waiting + " waiting)";
        }
    }

    record TaskStarted(TaskInstance task) implements Status {
        @Override
        public String toString() {
            return "task " + task.describe() + " started";
        }
    }

    record PlanFound(GoalInstance goal, Plan plan) implements Status {
        @Override
        public String toString() {
            return "plan for " + goal.describe() + ": "
                    + (plan.isEmpty() ? "no actions" : plan.actions().stream().map(GroundAction::toString).collect(Collectors.joining(", ")));
        }
    }

    /** Step {@code step} of {@code steps} of the current plan is about to run. */
    record ActionStarted(GoalInstance goal, GroundAction action, int step, int steps) implements Status {
        @Override
        public String toString() {
            return "action " + step + "/" + steps + " " + action + " started";
        }
    }

    record ActionSucceeded(GroundAction action) implements Status {
        @Override
        public String toString() {
            return "action " + action + " succeeded";
        }
    }

    record ActionFailed(GroundAction action, String reason) implements Status {
        @Override
        public String toString() {
            return "action " + action + " failed: " + reason;
        }
    }

    /** The {@code replan}-th of at most {@code maxReplans} re-plans of {@code goal}, after a failure for {@code reason}. */
    record Replanning(GoalInstance goal, int replan, int maxReplans, String reason) implements Status {
        @Override
        public String toString() {
            return "replanning " + goal.describe() + " (" + replan + " of " + maxReplans + "): " + reason;
        }
    }

    /** The goal holds: after the last action of its plan, or already when it was planned ({@code alreadyHeld}). */
    record GoalSatisfied(GoalInstance goal, boolean alreadyHeld) implements Status {
        @Override
        public String toString() {
            return "goal " + goal.describe() + (alreadyHeld ? " already satisfied" : " satisfied");
        }
    }

    record TaskCompleted(TaskInstance task) implements Status {
        @Override
        public String toString() {
            return "task " + task.describe() + " completed";
        }
    }

    /**
     * The task gave up at {@code goal}; {@code cause} is the kind of the failure that ended it (the last action's, when a
     * re-plan after it failed too): a fleet queues a task that the building's congestion ended again.
     */
    record TaskAborted(TaskInstance task, GoalInstance goal, String reason, Failure.Cause cause) implements Status {
        public TaskAborted(TaskInstance task, GoalInstance goal, String reason) {
            this(task, goal, reason, Failure.Cause.FAULT);
        }

        public TaskAborted {
            java.util.Objects.requireNonNull(cause, "cause");
        }

        @Override
        public String toString() {
            return "task " + task.describe() + " aborted at goal " + goal.describe() + ": " + reason;
        }
    }

    /** The architecture gave up on a goal; someone (a remote operator) has to take over. */
    record RemoteOperationRequested(TaskInstance task, GoalInstance goal, String reason) implements Status {
        @Override
        public String toString() {
            return "remote operation requested for task " + task.describe() + " at goal " + goal.describe() + ": " + reason;
        }
    }

    /** A component of the architecture threw; the step it belonged to counts as failed. */
    record ComponentFailed(ComponentFault fault) implements Status {
        @Override
        public String toString() {
            return "component " + fault;
        }
    }
}
