package org.triad.refarc;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Listens to RefArc's Status and hands every remote-operation request to a handler (e.g. one that
 * opens the robot's camera for an operator). Other status events are of no concern to it.
 */
public class RemoteOperator extends RemoteOperatorTOP {
    private final Consumer<Status.RemoteOperationRequested> handler;
    private final List<Status.RemoteOperationRequested> requests = Collections.synchronizedList(new ArrayList<>());

    public RemoteOperator(Consumer<Status.RemoteOperationRequested> handler) {
        this.handler = Objects.requireNonNull(handler, "RemoteOperator needs a handler");
    }

    /** A remote operator that only records the requests. */
    public RemoteOperator() {
        this(r -> { });
    }

    @Override
    protected void onStatus(Status message) {
        if (message instanceof Status.RemoteOperationRequested r) {
            requests.add(r);
            handler.accept(r);
        }
    }

    /** The requests received so far, oldest first. */
    public List<Status.RemoteOperationRequested> requests() {
        synchronized (requests) {
            return List.copyOf(requests);
        }
    }
}
