package org.triad.refarc;

import java.util.Objects;

/**
 * Plans one goal per request from a state fetched from the StateProvider right then. A goal that
 * already holds is reported as such without calling the back-end; the back-end runs as an activity
 * so a slow planner does not block the architecture.
 */
public class Planner extends PlannerTOP {
    private final GoalPlanner backEnd;
    private PlanRequest pending;

    public Planner(GoalPlanner backEnd) {
        this.backEnd = Objects.requireNonNull(backEnd, "Planner needs a GoalPlanner");
    }

    @Override
    protected void onRequest(PlanRequest message) {
        // A new request supersedes one whose state never came (the StateProvider faulted).
        pending = message;
        stateRequest.send(new StateRequest(message.requestId()));
    }

    @Override
    protected void onState(StateSnapshot message) {
        if (pending == null || pending.requestId() != message.requestId()) {
            throw new IllegalStateException(message + " does not answer the pending " + (pending == null ? "request (none)" : pending));
        }
        PlanRequest r = pending;
        pending = null;
        if (r.goal().isSatisfiedIn(message.state())) {
            plan.send(PlanResult.alreadySatisfied(r, message.state()));
            return;
        }
        startActivity("plan", r,
                () -> Objects.requireNonNull(backEnd.plan(r.goal(), r.then(), message.state()), "the GoalPlanner returned no outcome"),
                outcome -> plan.send(PlanResult.of(r, message.state(), outcome)));
    }
}
