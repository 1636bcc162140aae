package org.triad.runtime.component;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/** An outgoing port. Sending on an unconnected out port is allowed: nobody listens. */
public final class OutPort<T> extends Port<T> {
    private final List<Consumer<? super T>> observers = new CopyOnWriteArrayList<>();

    OutPort(Component owner, String name, Class<T> type) {
        super(owner, name, type);
    }

    /**
     * Sends a message to every connected receiver. The owner must be deployed on a scheduler; the
     * message must be a non-null instance of the port's type.
     */
    public void send(T message) {
        owner().scheduler().route(this, message);
    }

    /**
     * Lets the environment (a test, a driver, a UI) watch an out port of a root component. The
     * observer runs on the thread that sends, so it must be thread-safe in threaded mode.
     */
    public void observe(Consumer<? super T> observer) {
        if (owner().parent().isPresent()) {
            throw new IllegalStateException("only out ports of a root component can be observed; connect " + qualifiedName() + " to a port instead");
        }
        observers.add(observer);
    }

    List<Consumer<? super T>> observers() {
        return observers;
    }

    @Override
    String direction() {
        return "out";
    }
}
