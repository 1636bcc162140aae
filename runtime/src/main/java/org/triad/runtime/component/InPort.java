package org.triad.runtime.component;

/**
 * An incoming port. On an atomic component a handler registered with
 * {@link AtomicComponent#on(InPort, MessageHandler)} reacts to each message; on a composed component
 * the port forwards its messages to subcomponent ports.
 */
public final class InPort<T> extends Port<T> {
    InPort(Component owner, String name, Class<T> type) {
        super(owner, name, type);
    }

    @Override
    String direction() {
        return "in";
    }
}
