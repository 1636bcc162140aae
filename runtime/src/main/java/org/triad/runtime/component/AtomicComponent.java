package org.triad.runtime.component;

import java.util.HashMap;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * A component with behaviour: handlers react to messages arriving at its in ports and may send on
 * its out ports. A component handles one message at a time, whatever the scheduler. Work that takes
 * long (a robot action, a planner call) runs as an activity ({@link #startActivity}) so the
 * component and the rest of the architecture stay responsive.
 */
public abstract class AtomicComponent extends Component {
    private final Map<InPort<?>, MessageHandler<?>> handlers = new HashMap<>();
    final Queue<Envelope> mailbox = new ConcurrentLinkedQueue<>();
    final AtomicBoolean scheduled = new AtomicBoolean();

    /** Registers the behaviour for messages arriving at one of this component's in ports. */
    protected final <T> void on(InPort<T> port, MessageHandler<? super T> handler) {
        requireNotDeployed();
        if (port.owner() != this) {
            throw new IllegalArgumentException(path() + " cannot handle " + port + ": it belongs to another component");
        }
        if (handler == null) {
            throw new IllegalArgumentException("null handler for " + port);
        }
        if (handlers.putIfAbsent(port, handler) != null) {
            throw new IllegalStateException(port + " already has a handler");
        }
    }

    /**
     * Runs {@code work} on a worker and delivers its result to {@code onResult} as a message to this
     * component, handled serially with its other messages. If {@code work} throws, the result handler
     * is not called; a {@link ComponentFault} naming {@code activity NAME} and {@code subject} is
     * raised instead. A fault of the result handler names the same port and subject.
     *
     * @param name     names the activity in faults
     * @param subject  what the activity works on (e.g. the request), reported as the fault's message
     * @param work     the long-running work; it must not touch the component's state
     * @param onResult handles the result on the component's serial context
     */
    protected final <R> void startActivity(String name, Object subject, Callable<? extends R> work, MessageHandler<? super R> onResult) {
        if (work == null || onResult == null) {
            throw new IllegalArgumentException("an activity needs work and a result handler");
        }
        scheduler().startActivity(new Activity<>(this, name, subject, work, onResult));
    }

    /** Runs one envelope; whatever it throws becomes a fault. */
    final void process(Envelope envelope) {
        try {
            envelope.run();
        } catch (Throwable t) {
            try {
                scheduler().fault(this, envelope.label(), envelope.message(), t);
            } catch (RuntimeException reportFailed) {
                // Reporting must not kill the thread either; this is the last place to tell anyone.
                System.err.println("could not report fault of " + path() + " (" + t + "): " + reportFailed);
            }
        }
    }

    @SuppressWarnings("unchecked")
    final void handle(InPort<?> port, Object message) throws Exception {
        MessageHandler<Object> h = (MessageHandler<Object>) handlers.get(port);
        if (h == null) {
            throw new IllegalStateException("no handler for " + port);
        }
        h.handle(message);
    }
}
