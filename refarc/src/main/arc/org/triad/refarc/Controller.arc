package org.triad.refarc;

import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.ComponentFault;

/*
 * Drives task execution with the paper's semantics (Sect. 5): the goals of a task in order, each
 * planned from the state fetched right then; the actions of a plan in order; a failed planning, a
 * failed action (a false precondition included) or a fault of the component serving the request is
 * a failure, and after a failure the goal is re-planned, at most maxReplans times in a row; the next
 * failure aborts the task with a remote-operation request on status. "In a row" means without a
 * successful action in between: a successful action resets the count, and so does a new goal.
 * A refusal the planner proved (no plan reaches the goal from the state it planned from, e.g. a battery
 * too low for the trip) aborts at once when no action failed since the goal started: nothing has
 * changed the world since, so planning again would give the same answer. After a failed action the
 * proven refusal is re-planned like any failure (the world may be changing under the robot: a door
 * reopens, a lift recovers). A timeout, a spent budget, a fault and a refuted plan are never proven.
 * A planning failure that follows a failed action in the same row names that action's failure first
 * (cause): the planner's "no plan" from where a stuck lift left the robot is the consequence, the
 * lift's fault the reason, on the re-plan and on the abort. The abort carries the kind of that cause
 * (run.abortCause(refused): a proven refusal, the building's congestion, or a fault), so a fleet can
 * queue the task again after congestion and not hold a refusal against the robot.
 * Tasks that arrive meanwhile queue. Every step is reported on status.
 *
 * At most one request (plan or action) is outstanding; run (a TaskProgress) numbers requests, so a
 * reply or a fault is matched to it by request id. Hand-written in org.triad.refarc.Controller: how
 * a reply that matches no transition is reported (TOP pattern: generated ControllerTOP).
 */
component Controller {
  port in TaskInstance task;
  port in PlanResult plan;
  port in ActionResult actionResult;
  port in ComponentFault fault;
  port out PlanRequest planRequest;
  port out ActionRequest action;
  port out Status status;

  var TaskProgress run = new TaskProgress();
  var java.util.Deque<TaskInstance> waiting = new java.util.ArrayDeque<>();
  var int maxReplans = 3;
  var int failures = 0;
  var String reason = "";
  var String cause = "";
  /* an action failed (or its component faulted) since the current goal started */
  var boolean actionFailed = false;
  /* the last failure is a proven refusal with no failed action before it in this goal: abort at once */
  var boolean refused = false;

  automaton {
    initial state Idle;
    state Planning;
    state Executing;
    /* decisions, left at once by a transition without trigger */
    state NextGoal;
    state NextAction;
    state Failed;
    state TaskDone;

    Idle -> NextGoal on task / { run.start(task); status = new Status.TaskStarted(task); };
    Planning -> Planning on task / { waiting.add(task); status = new Status.TaskQueued(task, waiting.size()); };
    Executing -> Executing on task / { waiting.add(task); status = new Status.TaskQueued(task, waiting.size()); };

    NextGoal -> Planning [run.hasNextGoal()] / { run.nextGoal(); failures = 0; cause = ""; actionFailed = false; refused = false; planRequest = run.planRequest(); };
    NextGoal -> TaskDone [!run.hasNextGoal()] / { status = new Status.TaskCompleted(run.task()); };

    Planning -> NextGoal on plan [run.answers(plan) && plan.alreadySatisfied()] / {
      status = new Status.GoalSatisfied(run.goal(), true);
    };
    Planning -> NextAction on plan [run.answers(plan) && run.planFound(plan)] / {
      run.follow(plan);
      status = new Status.PlanFound(run.goal(), run.plan());
    };
    Planning -> Failed on plan [run.answers(plan) && run.planningFailed(plan)] / {
      reason = run.planningFailedAfter(cause, run.planningFailure(plan));
      refused = run.planningProven(plan) && !actionFailed;
    };

    NextAction -> Executing [run.hasNextAction()] / {
      status = new Status.ActionStarted(run.goal(), run.action(), run.actionNumber(), run.planSize());
      action = run.actionRequest();
    };
    NextAction -> NextGoal [!run.hasNextAction()] / { status = new Status.GoalSatisfied(run.goal(), false); };

    Executing -> NextAction on actionResult [run.answers(actionResult) && actionResult.succeeded()] / {
      status = new Status.ActionSucceeded(actionResult.action());
      run.actionDone();
      failures = 0;
      cause = "";
      run.noFailureCause();
    };
    Executing -> Failed on actionResult [run.answers(actionResult) && !actionResult.succeeded()] / {
      status = new Status.ActionFailed(actionResult.action(), actionResult.reason());
      reason = "action " + actionResult.action() + " failed: " + actionResult.reason();
      cause = reason;
      actionFailed = true;
      refused = false;
      run.failedAs(actionResult.cause());
    };

    Idle -> Idle on fault / { status = new Status.ComponentFailed(fault); };
    Planning -> Planning on fault [!run.concerns(fault)] / { status = new Status.ComponentFailed(fault); };
    Planning -> Failed on fault [run.concerns(fault)] / {
      status = new Status.ComponentFailed(fault);
      reason = run.planningFailedAfter(cause, run.faultReason(fault));
      refused = false;
    };
    Executing -> Executing on fault [!run.concerns(fault)] / { status = new Status.ComponentFailed(fault); };
    Executing -> Failed on fault [run.concerns(fault)] / {
      status = new Status.ComponentFailed(fault);
      status = new Status.ActionFailed(run.action(), run.faultReason(fault));
      reason = "action " + run.action() + " failed: " + run.faultReason(fault);
      cause = reason;
      actionFailed = true;
      refused = false;
      run.noFailureCause();
    };

    Failed -> Planning [!refused && failures < maxReplans] / {
      failures = failures + 1;
      status = new Status.Replanning(run.goal(), failures, maxReplans, reason);
      planRequest = run.planRequest();
    };
    Failed -> TaskDone [refused || failures >= maxReplans] / {
      status = new Status.TaskAborted(run.task(), run.goal(), reason, run.abortCause(refused));
      status = new Status.RemoteOperationRequested(run.task(), run.goal(), reason);
    };

    TaskDone -> NextGoal [!waiting.isEmpty()] / { run.start(waiting.poll()); status = new Status.TaskStarted(run.task()); };
    TaskDone -> Idle [waiting.isEmpty()] / { run.clear(); };
  }
}
