package org.triad.refarc;

import org.triad.runtime.component.AtomicComponent;
import org.triad.runtime.component.InPort;

/** Interface of the RemoteOperator as generated from {@code RemoteOperator.arc} (hand-written stand-in; TOP pattern). */
public abstract class RemoteOperatorTOP extends AtomicComponent {
    public final InPort<Status> status = inPort("status", Status.class);

    protected RemoteOperatorTOP() {
        on(status, this::onStatus);
    }

    protected abstract void onStatus(Status message) throws Exception;
}
