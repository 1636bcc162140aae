package org.triad.refarc;

import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;

/**
 * Where the Controller's automaton stands in its running task: the goal, the plan and the action,
 * and the one outstanding request, numbered so replies and faults are matched to it.
 */
public final class TaskProgress {
    private TaskInstance task;
    private int goalIndex;
    private Plan plan;
    private int actionIndex;
    private long outstanding;
    private long lastRequestId;

    /** The kind of the cause in the Controller's row of failures (see {@link #failedAs}). */
    private Failure.Cause failureCause = Failure.Cause.FAULT;

    public void start(TaskInstance t) {
        task = t;
        goalIndex = -1;
        plan = null;
        outstanding = 0;
        failureCause = Failure.Cause.FAULT;
    }

    public void clear() {
        task = null;
        plan = null;
        outstanding = 0;
    }

    public TaskInstance task() {
        return task;
    }

    public boolean hasNextGoal() {
        return goalIndex + 1 < task.goals().size();
    }

    public void nextGoal() {
        goalIndex++;
        plan = null;
        failureCause = Failure.Cause.FAULT;
    }

    /** The kind of the failure that the next abort reports (the last failed action's in this row of failures). */
    public void failedAs(Failure.Cause cause) {
        failureCause = cause == null ? Failure.Cause.FAULT : cause;
    }

    /** A success, a new goal or a component's fault: an abort now would be a fault. */
    public void noFailureCause() {
        failureCause = Failure.Cause.FAULT;
    }

    public Failure.Cause failureCause() {
        return failureCause;
    }

    /** The kind of an abort now: {@link Failure.Cause#REFUSED} for a proven refusal, else the last failure's ({@link #failureCause}). */
    public Failure.Cause abortCause(boolean refused) {
        return refused ? Failure.Cause.REFUSED : failureCause;
    }

    public GoalInstance goal() {
        return task.goals().get(goalIndex);
    }

    /** A new request for a plan of the current goal; it is the outstanding one from now on. */
    public PlanRequest planRequest() {
        outstanding = ++lastRequestId;
        return new PlanRequest(outstanding, goal(), task.goals().subList(goalIndex + 1, task.goals().size()));
    }

    /** Whether {@code reply} answers the outstanding request. */
    public boolean answers(Correlated reply) {
        return outstanding != 0 && reply.requestId() == outstanding;
    }

    public boolean planFound(PlanResult result) {
        return !result.alreadySatisfied() && result.outcome() instanceof PlanningOutcome.Planned;
    }

    public boolean planningFailed(PlanResult result) {
        return result.outcome() instanceof PlanningOutcome.Failed;
    }

    /** Whether the planner proved that no plan reaches the goal from the state it planned from. */
    public boolean planningProven(PlanResult result) {
        return result.outcome() instanceof PlanningOutcome.Failed f && f.proven();
    }

    public String planningFailure(PlanResult result) {
        return ((PlanningOutcome.Failed) result.outcome()).reason();
    }

    /** Takes the plan of {@code result} to execute from its first action. */
    public void follow(PlanResult result) {
        plan = ((PlanningOutcome.Planned) result.outcome()).plan();
        actionIndex = 0;
        outstanding = 0;
    }

    public Plan plan() {
        return plan;
    }

    public boolean hasNextAction() {
        return actionIndex < plan.size();
    }

    public GroundAction action() {
        return plan.actions().get(actionIndex);
    }

    /** The current action's position in the plan, from 1. */
    public int actionNumber() {
        return actionIndex + 1;
    }

    public int planSize() {
        return plan.size();
    }

    /** A new request to execute the current action; it is the outstanding one from now on. */
    public ActionRequest actionRequest() {
        outstanding = ++lastRequestId;
        return new ActionRequest(outstanding, action());
    }

    public void actionDone() {
        actionIndex++;
        outstanding = 0;
    }

    /** Whether a fault happened while serving the outstanding request. */
    public boolean concerns(ComponentFault fault) {
        return outstanding != 0 && fault.message() instanceof Correlated c && c.requestId() == outstanding;
    }

    /**
     * Why a goal failed at planning: {@code planning failed: <why>}, or, when an action of the same goal failed just
     * before (no action succeeded since), that action's failure first, since it is why the planner found no way on:
     * {@code action ride(lift, c7, d1) failed: lift 'lift' stopped between floors 0 and 1; planning from there failed: <why>}.
     *
     * @param cause the failure of the action that led to this planning, or empty
     */
    public String planningFailedAfter(String cause, String planningFailure) {
        return cause == null || cause.isEmpty() ? "planning failed: " + planningFailure
                : cause + "; planning from there failed: " + planningFailure;
    }

    public String faultReason(ComponentFault fault) {
        return "fault in " + fault.componentPath() + ": " + fault.causeDescription();
    }

    /** The outstanding request's id, 0 for none. */
    public long outstanding() {
        return outstanding;
    }
}
