package org.triad.refarc;

import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/**
 * Interface of the StateProvider as generated from {@code StateProvider.arc} (hand-written
 * stand-in; TOP pattern). One query/answer port pair per client, because an in port has one sender.
 */
public abstract class StateProviderTOP extends AtomicComponent {
    public final InPort<StateRequest> plannerQuery = inPort("plannerQuery", StateRequest.class);
    public final OutPort<StateSnapshot> plannerState = outPort("plannerState", StateSnapshot.class);
    public final InPort<StateRequest> executorQuery = inPort("executorQuery", StateRequest.class);
    public final OutPort<StateSnapshot> executorState = outPort("executorState", StateSnapshot.class);

    protected StateProviderTOP() {
        on(plannerQuery, this::onPlannerQuery);
        on(executorQuery, this::onExecutorQuery);
    }

    protected abstract void onPlannerQuery(StateRequest message) throws Exception;

    protected abstract void onExecutorQuery(StateRequest message) throws Exception;
}
