package org.triad.refarc;

import java.util.ArrayDeque;
import java.util.Deque;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;

/**
 * Drives task execution (Sect. 5 of the paper): satisfies the goals of a task in order, requests a
 * plan per goal, runs its actions in order, re-plans after a failure at most {@value #MAX_REPLANS}
 * times per goal and aborts with a remote-operation request at the next failure in a row. Tasks that
 * arrive while one runs wait in arrival order. Every step is reported on {@code status}.
 *
 * <p>At most one request (plan or action) is outstanding; replies and faults are matched to it by
 * request id, so a fault in any component serving that request fails exactly that step.
 */
public class Controller extends ControllerTOP {
    /** Re-plans allowed per goal after failures in a row; the next failure aborts the task. */
    public static final int MAX_REPLANS = 3;

    private enum Phase { IDLE, PLANNING, EXECUTING }

    private final Deque<TaskInstance> waiting = new ArrayDeque<>();
    private Phase phase = Phase.IDLE;
    private TaskInstance currentTask;
    private int goalIndex;
    private GoalInstance goal;
    private int failuresInRow;
    private Plan currentPlan;
    private int actionIndex;
    private long outstanding;
    private long lastRequestId;

    @Override
    protected void onTask(TaskInstance message) {
        if (phase == Phase.IDLE) {
            start(message);
        } else {
            waiting.add(message);
            status.send(new Status.TaskQueued(message, waiting.size()));
        }
    }

    @Override
    protected void onPlan(PlanResult message) {
        expect(Phase.PLANNING, message);
        outstanding = 0;
        if (message.alreadySatisfied()) {
            status.send(new Status.GoalSatisfied(goal, true));
            nextGoal();
        } else if (message.outcome() instanceof PlanningOutcome.Planned p) {
            status.send(new Status.PlanFound(goal, p.plan()));
            currentPlan = p.plan();
            actionIndex = 0;
            nextAction();
        } else {
            fail("planning failed: " + ((PlanningOutcome.Failed) message.outcome()).reason());
        }
    }

    @Override
    protected void onActionResult(ActionResult message) {
        expect(Phase.EXECUTING, message);
        outstanding = 0;
        if (message.succeeded()) {
            status.send(new Status.ActionSucceeded(message.action()));
            actionIndex++;
            nextAction();
        } else {
            status.send(new Status.ActionFailed(message.action(), message.reason()));
            fail("action " + message.action() + " failed: " + message.reason());
        }
    }

    @Override
    protected void onFault(ComponentFault message) {
        status.send(new Status.ComponentFailed(message));
        boolean concernsCurrentStep = outstanding != 0 && message.message() instanceof Correlated c && c.requestId() == outstanding;
        if (!concernsCurrentStep) {
            return;
        }
        outstanding = 0;
        String reason = "fault in " + message.componentPath() + ": " + message.causeDescription();
        if (phase == Phase.PLANNING) {
            fail("planning failed: " + reason);
        } else {
            GroundAction a = currentAction();
            status.send(new Status.ActionFailed(a, reason));
            fail("action " + a + " failed: " + reason);
        }
    }

    private void expect(Phase expected, Correlated reply) {
        if (phase != expected || reply.requestId() != outstanding) {
            throw new IllegalStateException("unexpected " + reply + " while " + phase.name().toLowerCase()
                    + (outstanding == 0 ? "" : " and waiting for request #" + outstanding));
        }
    }

    private void start(TaskInstance task) {
        currentTask = task;
        goalIndex = -1;
        status.send(new Status.TaskStarted(task));
        nextGoal();
    }

    private void nextGoal() {
        goalIndex++;
        failuresInRow = 0;
        if (goalIndex == currentTask.goals().size()) {
            status.send(new Status.TaskCompleted(currentTask));
            finishTask();
            return;
        }
        goal = currentTask.goals().get(goalIndex);
        requestPlan();
    }

    private void requestPlan() {
        phase = Phase.PLANNING;
        outstanding = ++lastRequestId;
        planRequest.send(new PlanRequest(outstanding, goal));
    }

    private void nextAction() {
        if (actionIndex == currentPlan.size()) {
            status.send(new Status.GoalSatisfied(goal, false));
            nextGoal();
            return;
        }
        phase = Phase.EXECUTING;
        outstanding = ++lastRequestId;
        status.send(new Status.ActionStarted(goal, currentAction(), actionIndex + 1, currentPlan.size()));
        action.send(new ActionRequest(outstanding, currentAction()));
    }

    private GroundAction currentAction() {
        return currentPlan.actions().get(actionIndex);
    }

    private void fail(String reason) {
        failuresInRow++;
        if (failuresInRow > MAX_REPLANS) {
            status.send(new Status.TaskAborted(currentTask, goal, reason));
            status.send(new Status.RemoteOperationRequested(currentTask, goal, reason));
            finishTask();
        } else {
            status.send(new Status.Replanning(goal, failuresInRow, MAX_REPLANS, reason));
            requestPlan();
        }
    }

    private void finishTask() {
        phase = Phase.IDLE;
        outstanding = 0;
        currentTask = null;
        goal = null;
        currentPlan = null;
        if (!waiting.isEmpty()) {
            start(waiting.poll());
        }
    }
}
