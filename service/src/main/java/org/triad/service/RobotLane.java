package org.triad.service;

import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.GoalPlanner;
import org.triad.refarc.PlanningOutcome;
import org.triad.refarc.RefArc;
import org.triad.refarc.StateSource;
import org.triad.refarc.Status;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.Scheduler;
import org.triad.runtime.component.ThreadedScheduler;

/**
 * One robot of the fleet with its own RefArc, deployed once for the service's lifetime on a scheduler
 * of its own, so that robots work in parallel. The service gives a lane one task at a time. To stop a
 * running task (cancel, robot taken offline) the lane refuses the task's next action and planning
 * call with the reason, so RefArc aborts it the way it aborts any task.
 */
final class RobotLane implements AutoCloseable {
    /** Receives every Status event of the lane's RefArc with the service's id of the task it belongs to. */
    interface Listener {
        void onStatus(RobotLane lane, long taskId, Status status);
    }

    private final FleetRobot robot;
    private final ThreadedScheduler scheduler;
    private final RefArc arc;
    private final Map<TaskInstance, Long> ids = Collections.synchronizedMap(new IdentityHashMap<>());
    private volatile boolean online = true;
    private volatile String offlineReason;
    /** Why the robot is gone (its platform reported it so, e.g. a VDA 5050 connection broken), or null while it is there. */
    private volatile String goneReason;
    private int abortedInARow;
    private volatile Long currentTask;
    private volatile String currentCall;
    private volatile String stopReason;
    /** Whether the stop ends the task aborted with a remote-operation request (its robot is gone) rather than queued again. */
    private volatile boolean stopAborts;
    private volatile List<String> plan = List.of();
    private volatile int step;

    RobotLane(FleetRobot robot, GoalPlanner planner, Listener listener) {
        this.robot = robot;
        this.scheduler = Scheduler.threaded(1);
        this.arc = new RefArc(robot.stateSource(), guard(planner), guard(robot.actionRunner()));
        arc.status.observe(status -> {
            Long id = taskOf(status);
            if (status instanceof Status.PlanFound p) {
                plan = p.plan().actions().stream().map(GroundAction::toString).toList();
                step = 0;
            } else if (status instanceof Status.ActionStarted a) {
                step = a.step();
            }
            if (id != null) {
                listener.onStatus(this, id, status);
            }
        });
        scheduler.deploy(arc);
    }

    private Long taskOf(Status s) {
        TaskInstance t = s instanceof Status.TaskStarted x ? x.task()
                : s instanceof Status.TaskCompleted x ? x.task()
                : s instanceof Status.TaskAborted x ? x.task()
                : s instanceof Status.RemoteOperationRequested x ? x.task()
                : s instanceof Status.TaskQueued x ? x.task() : null;
        return t == null ? currentTask : ids.get(t);
    }

    String name() {
        return robot.name();
    }

    FleetRobot robot() {
        return robot;
    }

    StateSource stateSource() {
        return robot.stateSource();
    }

    /** Whether the robot takes tasks: the operator (or the abort rule) has it online, and it is there. */
    boolean online() {
        return online && goneReason == null;
    }

    /** The platform reports the robot gone, for {@code reason}; it takes no task until {@link #back()}. */
    void gone(String reason) {
        goneReason = reason;
    }

    void back() {
        goneReason = null;
    }

    boolean isGone() {
        return goneReason != null;
    }

    void setOnline(boolean on) {
        online = on;
        offlineReason = on ? null : "taken offline by the operator";
        if (on) {
            abortedInARow = 0;
        }
    }

    /** Why the robot is out of dispatch (gone first, then the operator's or the abort rule's reason), or null. */
    String offlineReason() {
        String gone = goneReason;
        return gone != null ? "gone: " + gone : online ? null : offlineReason;
    }

    /**
     * Counts a task aborted on this robot; returns how many in a row. A robot whose tasks keep
     * aborting is taken out of dispatch (by the service) so that it stops taking work another robot could do.
     */
    synchronized int aborted() {
        return ++abortedInARow;
    }

    synchronized void completed() {
        abortedInARow = 0;
    }

    /** Takes the robot out of dispatch for {@code reason} (shown to the operator); the operator puts it back online. */
    void takeOut(String reason) {
        online = false;
        offlineReason = reason;
    }

    boolean idle() {
        return currentTask == null && !parking;
    }

    /** Whether the robot drives out of the others' way after its last task (see {@link #finished}): not idle meanwhile. */
    private volatile boolean parking;

    Optional<Long> currentTask() {
        return Optional.ofNullable(currentTask);
    }

    String currentCall() {
        return currentCall;
    }

    List<String> plan() {
        return plan;
    }

    int step() {
        return step;
    }

    /** Why the current task is being stopped, if it is. */
    Optional<String> stopReason() {
        return Optional.ofNullable(stopReason);
    }

    synchronized void start(long taskId, TaskInstance task) {
        if (currentTask != null) {
            throw new IllegalStateException("robot " + name() + " already runs task " + currentTask);
        }
        ids.put(task, taskId);
        currentTask = taskId;
        currentCall = task.describe();
        stopReason = null;
        stopAborts = false;
        plan = List.of();
        step = 0;
        scheduler.send(arc.task, task);
    }

    /** Asks RefArc to give up the current task at its next step, for {@code reason}; the service queues it again. */
    synchronized void stop(String reason) {
        if (currentTask != null) {
            stopReason = reason;
        }
    }

    /** Asks RefArc to give up the current task at its next step, for {@code reason}, to end aborted (the robot is gone). */
    synchronized void stopAborting(String reason) {
        if (currentTask != null) {
            stopReason = reason;
            stopAborts = true;
        }
    }

    /** Whether the current stop ends the task aborted (see {@link #stopAborting}). */
    boolean stopAborts() {
        return stopAborts;
    }

    /** The current task ended (completed or aborted): the lane takes the next. */
    synchronized void finished(long taskId) {
        if (currentTask != null && currentTask == taskId) {
            currentTask = null;
            currentCall = null;
            stopReason = null;
            stopAborts = false;
            plan = List.of();
            step = 0;
            // a robot left standing where the others pass (a task that congestion ended) gets out of their way before
            // it takes the next task or rests: it is not idle meanwhile, so no task is given to it while it drives
            parking = true;
            Thread park = new Thread(() -> {
                try {
                    robot.parkOutOfTheWay().ifPresent(line -> System.err.println("triad serve: " + name() + ": " + line));
                } catch (RuntimeException e) {
                    System.err.println("triad serve: " + name() + ": parking out of the way failed: " + e);
                } finally {
                    parking = false;
                }
            }, "park-" + name());
            park.setDaemon(true);
            park.start();
        }
    }

    /** Both of the planner's methods, so that the lookahead of {@code plan(goal, then, from)} reaches it. */
    private GoalPlanner guard(GoalPlanner planner) {
        return new GoalPlanner() {
            @Override
            public PlanningOutcome plan(GoalInstance goal, State from) throws Exception {
                String stop = stopReason;
                return stop != null ? PlanningOutcome.failed(stop) : planner.plan(goal, from);
            }

            @Override
            public PlanningOutcome plan(GoalInstance goal, List<GoalInstance> then, State from) throws Exception {
                String stop = stopReason;
                return stop != null ? PlanningOutcome.failed(stop) : planner.plan(goal, then, from);
            }
        };
    }

    private ActionRunner guard(ActionRunner runner) {
        return new ActionRunner() {
            @Override
            public Optional<String> violatedPrecondition(GroundAction action, State now) throws Exception {
                return runner.violatedPrecondition(action, now);
            }

            @Override
            public boolean execute(GroundAction action) throws Exception {
                return stopReason == null && runner.execute(action);
            }

            @Override
            public Optional<String> failureReason(GroundAction action) {
                String stop = stopReason;
                return stop != null ? Optional.of(stop) : runner.failureReason(action);
            }

            @Override
            public Optional<org.triad.runtime.app.Failure> failure(GroundAction action) {
                String stop = stopReason;
                return stop != null ? Optional.of(org.triad.runtime.app.Failure.fault(stop)) : runner.failure(action);
            }
        };
    }

    @Override
    public void close() {
        scheduler.close();
        try {
            robot.close();
        } catch (Exception e) {
            // the robot's connection is going away with the service anyway
        }
    }
}
