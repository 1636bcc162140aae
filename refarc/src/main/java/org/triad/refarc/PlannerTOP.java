package org.triad.refarc;

import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/** Interface of the Planner as generated from {@code Planner.arc} (hand-written stand-in; TOP pattern, see {@link ControllerTOP}). */
public abstract class PlannerTOP extends AtomicComponent {
    public final InPort<PlanRequest> request = inPort("request", PlanRequest.class);
    public final OutPort<StateRequest> stateRequest = outPort("stateRequest", StateRequest.class);
    public final InPort<StateSnapshot> state = inPort("state", StateSnapshot.class);
    public final OutPort<PlanResult> plan = outPort("plan", PlanResult.class);

    protected PlannerTOP() {
        on(request, this::onRequest);
        on(state, this::onState);
    }

    protected abstract void onRequest(PlanRequest message) throws Exception;

    protected abstract void onState(StateSnapshot message) throws Exception;
}
