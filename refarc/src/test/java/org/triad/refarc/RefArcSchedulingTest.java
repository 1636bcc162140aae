package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.refarc.Corridor.Execution;
import org.triad.refarc.Corridor.Planning;
import org.triad.refarc.Corridor.ScriptedPlanner;
import org.triad.refarc.Corridor.Task;
import org.triad.refarc.Corridor.World;
import org.triad.runtime.component.DeterministicScheduler;
import org.triad.runtime.component.Scheduler;
import org.triad.runtime.component.ThreadedScheduler;

/** Several tasks, long actions, and the threaded mode. */
class RefArcSchedulingTest {

    private static List<String> taskEvents(List<Status> statuses) {
        return statuses.stream()
                .filter(s -> s instanceof Status.TaskStarted || s instanceof Status.TaskQueued
                        || s instanceof Status.TaskCompleted || s instanceof Status.TaskAborted)
                .map(Status::toString).toList();
    }

    @Test
    void tasksArrivingTogetherQueueAndAllCompleteInOrder() {
        World world = new World("a");
        RefArc arc = new RefArc(world, new ScriptedPlanner(), world);
        List<Status> statuses = new ArrayList<>();
        arc.status.observe(statuses::add);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(arc);
        s.send(arc.task, Task.goTo("b"));
        s.send(arc.task, Task.goTo("d"));
        s.send(arc.task, Task.goTo("a"));
        s.runToCompletion();
        assertEquals(List.of(
                "task GoTo(b) started",
                "task GoTo(d) queued (1 waiting)",
                "task GoTo(a) queued (2 waiting)",
                "task GoTo(b) completed",
                "task GoTo(d) started",
                "task GoTo(d) completed",
                "task GoTo(a) started",
                "task GoTo(a) completed"), taskEvents(statuses));
        assertEquals(List.of("robot.move(a, b)", "robot.move(b, c)", "robot.move(c, d)",
                "robot.move(d, c)", "robot.move(c, b)", "robot.move(b, a)"), world.executed());
        assertTrue(s.unhandledFaults().isEmpty());
    }

    @Test
    void anAbortedTaskDoesNotStopTheQueue() {
        World world = new World("a");
        Planning f = Planning.fail("blocked");
        RefArc arc = new RefArc(world, new ScriptedPlanner(f, f, f, f), world);
        List<Status> statuses = new ArrayList<>();
        arc.status.observe(statuses::add);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(arc);
        s.send(arc.task, Task.goTo("e"));
        s.send(arc.task, Task.goTo("b"));
        s.runToCompletion();
        assertEquals(List.of(
                "task GoTo(e) started",
                "task GoTo(b) queued (1 waiting)",
                "task GoTo(e) aborted at goal IsAt(e): planning failed: blocked",
                "task GoTo(b) started",
                "task GoTo(b) completed"), taskEvents(statuses));
    }

    @Test
    void theArchitectureStaysResponsiveDuringALongAction() {
        World world = new World("a");
        RefArc arc = new RefArc(world, new ScriptedPlanner(), world);
        List<Status> statuses = new ArrayList<>();
        arc.status.observe(statuses::add);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(arc);
        s.send(arc.task, Task.goTo("b"));
        s.runUntilIdle();
        assertEquals(List.of("refArc.planner activity plan on plan request #1 for IsAt(b)"), s.pendingActivities());
        s.runNextActivity();
        s.runUntilIdle();
        // the robot is moving: the action is an activity in progress
        assertEquals(List.of("refArc.actionExecutor activity execute on action request #2 robot.move(a, b)"), s.pendingActivities());
        assertEquals("action 1/1 robot.move(a, b) started", statuses.get(statuses.size() - 1).toString());
        s.send(arc.task, Task.goTo("c"));
        s.runUntilIdle();
        assertEquals("task GoTo(c) queued (1 waiting)", statuses.get(statuses.size() - 1).toString());
        assertEquals(List.of(), world.executed(), "the queued task was accepted while the action had not finished");
        s.runToCompletion();
        assertEquals(List.of(
                "task GoTo(b) started",
                "task GoTo(c) queued (1 waiting)",
                "task GoTo(b) completed",
                "task GoTo(c) started",
                "task GoTo(c) completed"), taskEvents(statuses));
    }

    @Test
    void threadedModeReportsExactlyWhatDeterministicModeReports() throws Exception {
        // the same eventful scenario twice: a slip, a crash, a planning failure
        World reference = scenarioWorld();
        RefArcRun expected = new RefArcRunner(reference, scenarioPlanner(), reference).run(Task.goTo("c", "a"));
        World world = scenarioWorld();
        RefArc arc = new RefArc(world, scenarioPlanner(), world);
        List<Status> statuses = Collections.synchronizedList(new ArrayList<>());
        arc.status.observe(statuses::add);
        try (ThreadedScheduler s = Scheduler.threaded(2)) {
            s.deploy(arc);
            s.send(arc.task, Task.goTo("c", "a"));
            assertTrue(s.awaitIdle(Duration.ofSeconds(30)));
            assertTrue(s.unhandledFaults().isEmpty());
        }
        assertEquals(expected.log(), statuses.stream().map(Status::toString).toList());
        assertEquals(RefArcRun.Outcome.COMPLETED, expected.outcome());
        assertTrue(expected.log().size() > 15, "the scenario exercises failures: " + expected.log());
    }

    private static World scenarioWorld() {
        return new World("a").executions(Execution.slipTo("e"), Execution.OK, Execution.CRASH);
    }

    private static ScriptedPlanner scenarioPlanner() {
        return new ScriptedPlanner(Planning.SHORTEST, Planning.fail("door closed"));
    }
}
