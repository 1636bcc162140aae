package org.triad.refarc;

import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/** Interface of the ActionExecutor as generated from {@code ActionExecutor.arc} (hand-written stand-in; TOP pattern). */
public abstract class ActionExecutorTOP extends AtomicComponent {
    public final InPort<ActionRequest> action = inPort("action", ActionRequest.class);
    public final OutPort<StateRequest> stateRequest = outPort("stateRequest", StateRequest.class);
    public final InPort<StateSnapshot> state = inPort("state", StateSnapshot.class);
    public final OutPort<ActionResult> result = outPort("result", ActionResult.class);

    protected ActionExecutorTOP() {
        on(action, this::onAction);
        on(state, this::onState);
    }

    protected abstract void onAction(ActionRequest message) throws Exception;

    protected abstract void onState(StateSnapshot message) throws Exception;
}
