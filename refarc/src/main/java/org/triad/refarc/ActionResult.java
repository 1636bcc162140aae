package org.triad.refarc;

import org.triad.runtime.app.GroundAction;

/** ActionExecutor to Controller: whether the action ran successfully, and why not. */
public record ActionResult(long requestId, GroundAction action, boolean succeeded, String reason) implements Correlated {
    public static ActionResult success(ActionRequest r) {
        return new ActionResult(r.requestId(), r.action(), true, null);
    }

    public static ActionResult failure(ActionRequest r, String reason) {
        return new ActionResult(r.requestId(), r.action(), false, reason);
    }

    @Override
    public String toString() {
        return "action result #" + requestId + " " + action + (succeeded ? " succeeded" : " failed: " + reason);
    }
}
