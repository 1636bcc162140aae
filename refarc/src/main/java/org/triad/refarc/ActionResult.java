package org.triad.refarc;

import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GroundAction;

/** ActionExecutor to Controller: whether the action ran successfully, and why not (with the kind of cause). */
public record ActionResult(long requestId, GroundAction action, boolean succeeded, String reason, Failure.Cause cause) implements Correlated {
    public ActionResult(long requestId, GroundAction action, boolean succeeded, String reason) {
        this(requestId, action, succeeded, reason, succeeded ? null : Failure.Cause.FAULT);
    }

    public static ActionResult success(ActionRequest r) {
        return new ActionResult(r.requestId(), r.action(), true, null, null);
    }

    public static ActionResult failure(ActionRequest r, String reason) {
        return new ActionResult(r.requestId(), r.action(), false, reason, Failure.Cause.FAULT);
    }

    public static ActionResult failure(ActionRequest r, String reason, Failure.Cause cause) {
        return new ActionResult(r.requestId(), r.action(), false, reason, cause);
    }

    @Override
    public String toString() {
        return "action result #" + requestId + " " + action + (succeeded ? " succeeded" : " failed: " + reason);
    }
}
