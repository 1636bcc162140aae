package org.triad.refarc;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.component.DeterministicScheduler;
import org.triad.runtime.component.Scheduler;

/**
 * Runs one task to completion on a fresh {@link RefArc} in deterministic mode, synchronously, and
 * returns everything it reported: for tests, dry runs and the command line.
 */
public final class RefArcRunner {
    private final StateSource stateSource;
    private final GoalPlanner goalPlanner;
    private final ActionRunner actionRunner;

    public RefArcRunner(StateSource stateSource, GoalPlanner goalPlanner, ActionRunner actionRunner) {
        this.stateSource = Objects.requireNonNull(stateSource, "a StateSource is required");
        this.goalPlanner = Objects.requireNonNull(goalPlanner, "a GoalPlanner is required");
        this.actionRunner = Objects.requireNonNull(actionRunner, "an ActionRunner is required");
    }

    public RefArcRun run(TaskInstance task) {
        return run(task, status -> { });
    }

    /** Like {@link #run(TaskInstance)}, also handing every status event to {@code observer} as it happens (progress output). */
    public RefArcRun run(TaskInstance task, Consumer<? super Status> observer) {
        Objects.requireNonNull(observer, "an observer is required");
        RefArc arc = new RefArc(stateSource, goalPlanner, actionRunner);
        List<Status> statuses = new ArrayList<>();
        arc.status.observe(statuses::add);
        arc.status.observe(observer);
        try (DeterministicScheduler scheduler = Scheduler.deterministic()) {
            scheduler.deploy(arc);
            scheduler.send(arc.task, task);
            scheduler.runToCompletion();
            return new RefArcRun(task, outcomeOf(task, statuses), statuses, scheduler.unhandledFaults());
        }
    }

    private static RefArcRun.Outcome outcomeOf(TaskInstance task, List<Status> statuses) {
        for (Status s : statuses) {
            if (s instanceof Status.TaskCompleted c && c.task() == task) {
                return RefArcRun.Outcome.COMPLETED;
            }
            if (s instanceof Status.TaskAborted a && a.task() == task) {
                return RefArcRun.Outcome.ABORTED;
            }
        }
        throw new IllegalStateException("task " + task.describe() + " neither completed nor aborted; status was " + statuses);
    }
}
