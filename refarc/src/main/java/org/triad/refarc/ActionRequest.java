package org.triad.refarc;

import org.triad.runtime.app.GroundAction;

/** Controller to ActionExecutor: check the precondition of this action and execute it. */
public record ActionRequest(long requestId, GroundAction action) implements Correlated {
    @Override
    public String toString() {
        return "action request #" + requestId + " " + action;
    }
}
