package org.triad.runtime.component;

/** Reacts to one message. An exception becomes a {@link ComponentFault}; it never kills a thread. */
@FunctionalInterface
public interface MessageHandler<T> {
    void handle(T message) throws Exception;
}
