package org.triad.refarc;

import java.util.Objects;
import java.util.Optional;

import org.triad.runtime.app.Failure;

/**
 * Executes one action per request: fetches the state right before execution, checks the action's
 * precondition against it, and runs the action as an activity so the architecture stays responsive
 * while the robot works.
 */
public class ActionExecutor extends ActionExecutorTOP {
    private final ActionRunner runner;
    private ActionRequest pending;

    public ActionExecutor(ActionRunner runner) {
        this.runner = Objects.requireNonNull(runner, "ActionExecutor needs an ActionRunner");
    }

    @Override
    protected void onAction(ActionRequest message) {
        pending = message;
        stateRequest.send(new StateRequest(message.requestId()));
    }

    @Override
    protected void onState(StateSnapshot message) throws Exception {
        if (pending == null || pending.requestId() != message.requestId()) {
            throw new IllegalStateException(message + " does not answer the pending " + (pending == null ? "request (none)" : pending));
        }
        ActionRequest r = pending;
        pending = null;
        Optional<String> violated = Objects.requireNonNull(runner.violatedPrecondition(r.action(), message.state()),
                "the ActionRunner returned null instead of an Optional");
        if (violated.isPresent()) {
            result.send(ActionResult.failure(r, "precondition violated: " + violated.get()));
            return;
        }
        startActivity("execute", r, () -> runner.execute(r.action()),
                ok -> result.send(ok ? ActionResult.success(r) : failed(r)));
    }

    private ActionResult failed(ActionRequest r) {
        Optional<Failure> f = runner.failure(r.action());
        return f == null || f.isEmpty() ? ActionResult.failure(r, "the platform reported failure")
                : ActionResult.failure(r, "the platform reported failure: " + f.get().reason(), f.get().cause());
    }
}
