package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.refarc.Corridor.Execution;
import org.triad.refarc.Corridor.ScriptedPlanner;
import org.triad.refarc.Corridor.Task;
import org.triad.refarc.Corridor.World;

/**
 * What "the 4th failure in a row aborts" means: failures count until an action succeeds (or the
 * next goal starts); a successful action in between starts the count again.
 */
class FailuresInARowTest {

    private static RefArcRun run(World world, Task task) {
        RefArcRun r = new RefArcRunner(world, new ScriptedPlanner(), world).run(task);
        assertTrue(r.unhandledFaults().isEmpty(), () -> "unhandled faults " + r.unhandledFaults());
        return r;
    }

    private static List<String> replansAndEnd(RefArcRun r) {
        return r.log().stream().filter(l -> l.startsWith("replanning") || l.startsWith("task GoTo(e) aborted") || l.endsWith("completed"))
                .toList();
    }

    @Test
    void fourFailedActionsInARowAbort() {
        World world = new World("a").executions(Execution.FAIL, Execution.FAIL, Execution.FAIL, Execution.FAIL);
        RefArcRun r = run(world, Task.goTo("e"));
        assertEquals(RefArcRun.Outcome.ABORTED, r.outcome());
        assertEquals(List.of(
                "replanning IsAt(e) (1 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(e) (2 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(e) (3 of 3): action robot.move(a, b) failed: the platform reported failure",
                "task GoTo(e) aborted at goal IsAt(e): action robot.move(a, b) failed: the platform reported failure"), replansAndEnd(r));
    }

    @Test
    void aSuccessfulActionBetweenFailuresStartsTheCountAgain() {
        // failures at the 1st, 2nd, 3rd and 5th move: the 4th move succeeds in between, so the 5th is the first failure of a new row
        World world = new World("a").executions(Execution.FAIL, Execution.FAIL, Execution.FAIL, Execution.OK, Execution.FAIL);
        RefArcRun r = run(world, Task.goTo("e"));
        assertEquals(RefArcRun.Outcome.COMPLETED, r.outcome());
        assertEquals(List.of(
                "replanning IsAt(e) (1 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(e) (2 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(e) (3 of 3): action robot.move(a, b) failed: the platform reported failure",
                "replanning IsAt(e) (1 of 3): action robot.move(b, c) failed: the platform reported failure",
                "task GoTo(e) completed"), replansAndEnd(r));
        assertEquals("e", world.loc);
    }
}
