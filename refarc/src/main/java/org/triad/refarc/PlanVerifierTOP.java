package org.triad.refarc;

import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.InPort;
import org.triad.runtime.component.OutPort;

/** Interface of the PlanVerifier as generated from {@code PlanVerifier.arc} (hand-written stand-in; TOP pattern). */
public abstract class PlanVerifierTOP extends AtomicComponent {
    public final InPort<PlanResult> proposed = inPort("proposed", PlanResult.class);
    public final OutPort<PlanResult> verified = outPort("verified", PlanResult.class);

    protected PlanVerifierTOP() {
        on(proposed, this::onProposed);
    }

    protected abstract void onProposed(PlanResult message) throws Exception;
}
