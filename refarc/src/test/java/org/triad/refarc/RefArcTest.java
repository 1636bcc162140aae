package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.triad.refarc.Corridor.move;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.refarc.Corridor.Execution;
import org.triad.refarc.Corridor.Planning;
import org.triad.refarc.Corridor.ScriptedPlanner;
import org.triad.refarc.Corridor.Task;
import org.triad.refarc.Corridor.World;

/** The execution semantics of RefArc (Sect. 5 of the paper), one task per test through {@link RefArcRunner}. */
class RefArcTest {

    private static RefArcRun run(World world, ScriptedPlanner planner, Task task) {
        RefArcRun r = new RefArcRunner(world, planner, world).run(task);
        assertTrue(r.unhandledFaults().isEmpty(), () -> "unhandled faults " + r.unhandledFaults());
        return r;
    }

    @Test
    void goalsAreSatisfiedInOrderAndEveryStepIsReported() {
        World world = new World("a");
        ScriptedPlanner planner = new ScriptedPlanner();
        RefArcRun r = run(world, planner, Task.goTo("b", "d"));
        assertEquals(List.of(
                "task GoTo(b, d) started",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "plan for IsAt(d): robot.move(b, c), robot.move(c, d)",
                "action 1/2 robot.move(b, c) started",
                "action robot.move(b, c) succeeded",
                "action 2/2 robot.move(c, d) started",
                "action robot.move(c, d) succeeded",
                "goal IsAt(d) satisfied",
                "task GoTo(b, d) completed"), r.log());
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(List.of("IsAt(b) from a", "IsAt(d) from b"), planner.fromLocations);
        // the state is fetched for planning, and again right before each precondition check
        assertEquals(List.of(
                "fetch a", "fetch a", "check robot.move(a, b)", "execute robot.move(a, b)",
                "fetch b", "fetch b", "check robot.move(b, c)", "execute robot.move(b, c)",
                "fetch c", "check robot.move(c, d)", "execute robot.move(c, d)"), world.log);
    }

    /** Issue #22: the Planner gets the rest of the task, so that a goal's plan does not strand the robot. */
    @Test
    void eachGoalIsPlannedWithTheRestOfItsTask() {
        ScriptedPlanner planner = new ScriptedPlanner();
        RefArcRun r = run(new World("a"), planner, Task.goTo("b", "d", "c"));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(List.of("IsAt(b) then [IsAt(d), IsAt(c)]", "IsAt(d) then [IsAt(c)]", "IsAt(c) then []"), planner.lookaheads);
    }

    @Test
    void aGoalThatAlreadyHoldsNeedsNoPlanningAndNoActions() {
        World world = new World("a");
        ScriptedPlanner planner = new ScriptedPlanner();
        RefArcRun r = run(world, planner, Task.goTo("a", "b"));
        assertEquals(List.of(
                "task GoTo(a, b) started",
                "goal IsAt(a) already satisfied",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "task GoTo(a, b) completed"), r.log());
        assertEquals(List.of("IsAt(b) from a"), planner.fromLocations);
    }

    @Test
    void aTaskWithoutGoalsCompletesAtOnce() {
        RefArcRun r = run(new World("a"), new ScriptedPlanner(), Task.goTo());
        assertEquals(List.of("task GoTo() started", "task GoTo() completed"), r.log());
    }

    @Test
    void eachPlanningStartsFromTheStateFetchedAtThatMoment() {
        World world = new World("a").executions(Execution.slipTo("d"));
        ScriptedPlanner planner = new ScriptedPlanner();
        RefArcRun r = run(world, planner, Task.goTo("c"));
        assertEquals(List.of(
                "task GoTo(c) started",
                "plan for IsAt(c): robot.move(a, b), robot.move(b, c)",
                "action 1/2 robot.move(a, b) started",
                "action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(c) (1 of 3): action robot.move(a, b) failed: the platform reported failure",
                "plan for IsAt(c): robot.move(d, c)",
                "action 1/1 robot.move(d, c) started",
                "action robot.move(d, c) succeeded",
                "goal IsAt(c) satisfied",
                "task GoTo(c) completed"), r.log());
        assertEquals(List.of("IsAt(c) from a", "IsAt(c) from d"), planner.fromLocations);
    }

    @Test
    void planningIsRetriedThreeTimes() {
        ScriptedPlanner planner = new ScriptedPlanner(Planning.fail("no route 1"), Planning.fail("no route 2"), Planning.fail("no route 3"));
        RefArcRun r = run(new World("a"), planner, Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "replanning IsAt(b) (1 of 3): planning failed: no route 1",
                "replanning IsAt(b) (2 of 3): planning failed: no route 2",
                "replanning IsAt(b) (3 of 3): planning failed: no route 3",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "task GoTo(b) completed"), r.log());
        assertEquals(4, planner.calls());
    }

    @Test
    void theFourthPlanningFailureInARowAbortsWithARemoteOperationRequest() {
        World world = new World("a");
        ScriptedPlanner planner = ScriptedPlanner.thenAlways(Planning.fail("no route 5"),
                Planning.fail("no route 1"), Planning.fail("no route 2"), Planning.fail("no route 3"), Planning.fail("no route 4"));
        RefArcRun r = run(world, planner, Task.goTo("b", "c"));
        assertEquals(List.of(
                "task GoTo(b, c) started",
                "replanning IsAt(b) (1 of 3): planning failed: no route 1",
                "replanning IsAt(b) (2 of 3): planning failed: no route 2",
                "replanning IsAt(b) (3 of 3): planning failed: no route 3",
                "task GoTo(b, c) aborted at goal IsAt(b): planning failed: no route 4",
                "remote operation requested for task GoTo(b, c) at goal IsAt(b): planning failed: no route 4"), r.log());
        assertEquals(RefArcRun.Outcome.ABORTED, r.outcome());
        assertEquals(4, planner.calls(), "no fifth attempt, and the second goal is never planned");
        assertEquals(List.of(), world.executed());
        Status.RemoteOperationRequested request = (Status.RemoteOperationRequested) r.statuses().get(5);
        assertEquals("GoTo(b, c)", request.task().describe());
        assertEquals("IsAt(b)", request.goal().describe());
        assertEquals(org.triad.runtime.app.Failure.Cause.FAULT, abortCause(r), "failures the planner did not prove are a fault");
    }

    /** Issue #22: a refusal the planner proved (a battery too low for the trip) is not planned again from the same state. */
    @Test
    void aProvenRefusalAbortsAtOnce() {
        World world = new World("a");
        ScriptedPlanner planner = ScriptedPlanner.thenAlways(Planning.refuse("battery is 5.0 and the trip needs 29.0"));
        RefArcRun r = run(world, planner, Task.goTo("b", "c"));
        assertEquals(List.of(
                "task GoTo(b, c) started",
                "task GoTo(b, c) aborted at goal IsAt(b): planning failed: battery is 5.0 and the trip needs 29.0",
                "remote operation requested for task GoTo(b, c) at goal IsAt(b): planning failed: battery is 5.0 and the trip needs 29.0"), r.log());
        assertEquals(RefArcRun.Outcome.ABORTED, r.outcome());
        assertEquals(1, planner.calls(), "planned once: the answer cannot change from an unchanged state");
        assertEquals(List.of(), world.executed());
        assertEquals(org.triad.runtime.app.Failure.Cause.REFUSED, abortCause(r), "a proven refusal is not a fault");
    }

    private static org.triad.runtime.app.Failure.Cause abortCause(RefArcRun r) {
        return r.statuses().stream().filter(Status.TaskAborted.class::isInstance).map(Status.TaskAborted.class::cast)
                .findFirst().orElseThrow().cause();
    }

    /**
     * After a failed action a proven refusal is re-planned like any failure (the world changes under the robot),
     * and a new goal starts clean: its proven refusal aborts at once.
     */
    @Test
    void aProvenRefusalAfterAFailedActionOfTheSameGoalIsReplanned() {
        World world = new World("a").executions(Execution.FAIL);
        ScriptedPlanner planner = new ScriptedPlanner(Planning.SHORTEST, Planning.refuse("door closed"), Planning.SHORTEST,
                Planning.refuse("battery is 5.0 and the trip needs 29.0"));
        RefArcRun r = run(world, planner, Task.goTo("b", "c"));
        assertEquals(List.of(
                "task GoTo(b, c) started",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(b) (1 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(b) (2 of 3): action robot.move(a, b) failed: the platform reported failure; planning from there failed: door closed",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "task GoTo(b, c) aborted at goal IsAt(c): planning failed: battery is 5.0 and the trip needs 29.0",
                "remote operation requested for task GoTo(b, c) at goal IsAt(c): planning failed: battery is 5.0 and the trip needs 29.0"), r.log());
        assertEquals(4, planner.calls());
        assertEquals(org.triad.runtime.app.Failure.Cause.REFUSED, abortCause(r), "the new goal's refusal is proven and nothing failed since");
    }

    @Test
    void aViolatedPreconditionIsDetectedOnAFreshStateAndTriggersReplanning() {
        // someone pushes the robot to e right before the precondition of the first action is checked
        World world = new World("a").beforeFetch(2, w -> w.loc = "e");
        ScriptedPlanner planner = new ScriptedPlanner();
        RefArcRun r = run(world, planner, Task.goTo("c"));
        assertEquals(List.of(
                "task GoTo(c) started",
                "plan for IsAt(c): robot.move(a, b), robot.move(b, c)",
                "action 1/2 robot.move(a, b) started",
                "action robot.move(a, b) failed: precondition violated: robot.loc() == a does not hold (robot is at e)",
                "replanning IsAt(c) (1 of 3): action robot.move(a, b) failed: precondition violated: robot.loc() == a does not hold (robot is at e)",
                "plan for IsAt(c): robot.move(e, d), robot.move(d, c)",
                "action 1/2 robot.move(e, d) started",
                "action robot.move(e, d) succeeded",
                "action 2/2 robot.move(d, c) started",
                "action robot.move(d, c) succeeded",
                "goal IsAt(c) satisfied",
                "task GoTo(c) completed"), r.log());
        assertEquals(List.of("robot.move(e, d)", "robot.move(d, c)"), world.executed());
        assertEquals(List.of("IsAt(c) from a", "IsAt(c) from e"), planner.fromLocations);
    }

    @Test
    void anActionThatThrowsIsAFaultOnStatusAndAFailedStep() {
        World world = new World("a").executions(Execution.CRASH);
        RefArcRun r = run(world, new ScriptedPlanner(), Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "component fault in refArc.actionExecutor at activity execute handling action request #2 robot.move(a, b): IOException: motor stalled",
                "action robot.move(a, b) failed: fault in refArc.actionExecutor: IOException: motor stalled",
                "replanning IsAt(b) (1 of 3): action robot.move(a, b) failed: fault in refArc.actionExecutor: IOException: motor stalled",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "action robot.move(a, b) succeeded",
                "goal IsAt(b) satisfied",
                "task GoTo(b) completed"), r.log());
        Status.ComponentFailed f = (Status.ComponentFailed) r.statuses().get(3);
        assertEquals(java.io.IOException.class, f.fault().cause().getClass());
    }

    @Test
    void failuresOfDifferentKindsShareOneBudgetPerGoal() {
        // plan fails; plan ok but action fails; plan ok but precondition fails; plan fails: abort
        World world = new World("a").executions(Execution.FAIL).beforeFetch(5, w -> w.loc = "e");
        ScriptedPlanner planner = new ScriptedPlanner(Planning.fail("busy"), Planning.SHORTEST, Planning.SHORTEST, Planning.fail("lost"));
        RefArcRun r = run(world, planner, Task.goTo("c"));
        assertEquals(RefArcRun.Outcome.ABORTED, r.outcome());
        assertEquals(4, planner.calls());
        assertEquals(List.of(
                "replanning IsAt(c) (1 of 3): planning failed: busy",
                "replanning IsAt(c) (2 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(c) (3 of 3): action robot.move(a, b) failed: precondition violated: robot.loc() == a does not hold (robot is at e)",
                // the planning that failed last followed a failed action: the abort names that action's failure first
                "task GoTo(c) aborted at goal IsAt(c): action robot.move(a, b) failed: precondition violated: robot.loc() == a does not hold"
                        + " (robot is at e); planning from there failed: lost",
                "remote operation requested for task GoTo(c) at goal IsAt(c): action robot.move(a, b) failed: precondition violated:"
                        + " robot.loc() == a does not hold (robot is at e); planning from there failed: lost"),
                r.log().stream().filter(l -> l.startsWith("replanning") || l.startsWith("task GoTo(c) aborted") || l.startsWith("remote")).toList());
    }

    @Test
    void satisfyingAGoalResetsTheBudget() {
        Planning f = Planning.fail("not now");
        ScriptedPlanner planner = new ScriptedPlanner(f, f, f, Planning.SHORTEST, f, f, f, Planning.SHORTEST);
        RefArcRun r = run(new World("a"), planner, Task.goTo("b", "c"));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(8, planner.calls());
        assertEquals(6, r.statuses().stream().filter(s -> s instanceof Status.Replanning).count());
        assertEquals(List.of("goal IsAt(b) satisfied", "goal IsAt(c) satisfied"),
                r.log().stream().filter(l -> l.startsWith("goal")).toList());
    }

    @Test
    void aFaultWhileFetchingStateForPlanningFailsThatPlanning() {
        RefArcRun r = run(new World("a").failFetch(1), new ScriptedPlanner(), Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "component fault in refArc.stateProvider at plannerQuery handling state request #1: IllegalStateException: sensor offline",
                "replanning IsAt(b) (1 of 3): planning failed: fault in refArc.stateProvider: IllegalStateException: sensor offline",
                "plan for IsAt(b): robot.move(a, b)"), r.log().subList(0, 4));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
    }

    @Test
    void aPlannerThatThrowsFailsThatPlanning() {
        ScriptedPlanner planner = new ScriptedPlanner(Planning.crash("PDDL translation failed"));
        RefArcRun r = run(new World("a"), planner, Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "component fault in refArc.planner at activity plan handling plan request #1 for IsAt(b): IllegalStateException: PDDL translation failed",
                "replanning IsAt(b) (1 of 3): planning failed: fault in refArc.planner: IllegalStateException: PDDL translation failed",
                "plan for IsAt(b): robot.move(a, b)"), r.log().subList(0, 4));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(2, planner.calls());
    }

    @Test
    void aPlannerThatReturnsNothingIsAFaultToo() {
        ScriptedPlanner planner = new ScriptedPlanner((g, from) -> null);
        RefArcRun r = run(new World("a"), planner, Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "component fault in refArc.planner at activity plan handling plan request #1 for IsAt(b): NullPointerException: the GoalPlanner returned no outcome",
                "replanning IsAt(b) (1 of 3): planning failed: fault in refArc.planner: NullPointerException: the GoalPlanner returned no outcome"),
                r.log().subList(0, 3));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
    }

    @Test
    void aPreconditionCheckThatThrowsFailsThatAction() {
        World world = new World("a").crashCheck(1);
        RefArcRun r = run(world, new ScriptedPlanner(), Task.goTo("b"));
        assertEquals(List.of(
                "task GoTo(b) started",
                "plan for IsAt(b): robot.move(a, b)",
                "action 1/1 robot.move(a, b) started",
                "component fault in refArc.actionExecutor at state handling state #2: IllegalArgumentException: unknown action",
                "action robot.move(a, b) failed: fault in refArc.actionExecutor: IllegalArgumentException: unknown action",
                "replanning IsAt(b) (1 of 3): action robot.move(a, b) failed: fault in refArc.actionExecutor: IllegalArgumentException: unknown action"),
                r.log().subList(0, 6));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(List.of("robot.move(a, b)"), world.executed());
    }

    @Test
    void fourFaultsInARowAbortLikeAnyOtherFailures() {
        World world = new World("a").executions(Execution.CRASH, Execution.CRASH, Execution.CRASH, Execution.CRASH);
        RefArcRun r = run(world, new ScriptedPlanner(), Task.goTo("b"));
        assertEquals(RefArcRun.Outcome.ABORTED, r.outcome());
        assertEquals(4, r.statuses().stream().filter(s -> s instanceof Status.ComponentFailed).count());
        assertEquals("remote operation requested for task GoTo(b) at goal IsAt(b): action robot.move(a, b) failed: fault in refArc.actionExecutor: IOException: motor stalled",
                r.log().get(r.log().size() - 1));
    }

    @Test
    void statusEventsReadWell() {
        Task t = Task.goTo("b");
        Corridor.IsAt g = new Corridor.IsAt("b");
        assertEquals("task GoTo(b) queued (2 waiting)", new Status.TaskQueued(t, 2).toString());
        assertEquals("plan for IsAt(b): no actions", new Status.PlanFound(g, new org.triad.runtime.app.Plan(List.of())).toString());
        assertEquals("action 2/3 robot.move(a, b) started", new Status.ActionStarted(g, move("a", "b"), 2, 3).toString());
    }
}
