package org.triad.tests.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.triad.examples.hospital.HospitalRun;
import org.triad.refarc.Status;

/** Checks on the Status stream of a run in the simulated hospital. */
final class HospitalRunAssertions {
    private HospitalRunAssertions() {
    }

    /** The task's milestones in order: started, each plan and satisfied goal, completed or aborted (actions left out). */
    static List<String> milestones(HospitalRun run) {
        return run.refArc().statuses().stream()
                .filter(s -> s instanceof Status.TaskStarted || s instanceof Status.PlanFound || s instanceof Status.GoalSatisfied
                        || s instanceof Status.Replanning || s instanceof Status.TaskCompleted || s instanceof Status.TaskAborted
                        || s instanceof Status.RemoteOperationRequested)
                .map(Status::toString).toList();
    }

    /** Every action started was reported back as succeeded, in the order of the plans. */
    static void allActionsSucceeded(HospitalRun run) {
        List<Status> statuses = run.refArc().statuses();
        int started = 0;
        for (int i = 0; i < statuses.size(); i++) {
            if (statuses.get(i) instanceof Status.ActionStarted s) {
                started++;
                assertTrue(i + 1 < statuses.size() && statuses.get(i + 1) instanceof Status.ActionSucceeded ok
                        && ok.action().equals(s.action()), () -> "not succeeded: " + s + " in\n" + String.join("\n", run.refArc().log()));
            }
        }
        assertTrue(started > 0, "no actions ran");
        assertEquals(List.of(), run.refArc().unhandledFaults());
        assertTrue(run.platform().stream().allMatch(e -> e.success()), () -> run.platform().toString());
    }

    static String log(HospitalRun run) {
        return String.join("\n", run.refArc().log()) + "\nplatform:\n"
                + String.join("\n", run.platform().stream().map(Object::toString).toList());
    }
}
