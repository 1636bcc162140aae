package org.triad.refarc;

import java.util.Objects;
import org.triad.runtime.component.OutPort;

/** Answers state queries of the Planner and the ActionExecutor with a state fetched at that moment. */
public class StateProvider extends StateProviderTOP {
    private final StateSource source;

    public StateProvider(StateSource source) {
        this.source = Objects.requireNonNull(source, "StateProvider needs a StateSource");
    }

    @Override
    protected void onPlannerQuery(StateRequest message) throws Exception {
        answer(message, plannerState);
    }

    @Override
    protected void onExecutorQuery(StateRequest message) throws Exception {
        answer(message, executorState);
    }

    private void answer(StateRequest request, OutPort<StateSnapshot> to) throws Exception {
        to.send(new StateSnapshot(request.requestId(),
                Objects.requireNonNull(source.currentState(), "the StateSource returned no state")));
    }
}
