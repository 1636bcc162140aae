package org.triad.runtime.component;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Runs a deployed component architecture: routes messages along connectors, runs handlers and
 * activities, and turns exceptions into {@link ComponentFault}s. Two modes:
 * {@link DeterministicScheduler} (single thread, FIFO, for tests) and {@link ThreadedScheduler}.
 */
public abstract class Scheduler implements AutoCloseable {
    private final List<ComponentFault> unhandled = new ArrayList<>();
    private volatile Consumer<ComponentFault> faultListener;
    private Component root;

    public static DeterministicScheduler deterministic() {
        return new DeterministicScheduler();
    }

    /** A threaded scheduler whose components share {@code threads} threads. */
    public static ThreadedScheduler threaded(int threads) {
        return new ThreadedScheduler(threads);
    }

    /** Binds a root component and its whole subtree to this scheduler; freezes their structure. */
    public final synchronized void deploy(Component rootComponent) {
        if (root != null) {
            throw new IllegalStateException("this scheduler already runs " + root.path());
        }
        if (rootComponent.parent().isPresent()) {
            throw new IllegalArgumentException(rootComponent.path() + " is a subcomponent; deploy its root");
        }
        if (rootComponent.isDeployed()) {
            throw new IllegalStateException(rootComponent.path() + " is already deployed");
        }
        rootComponent.deployOn(this);
        root = rootComponent;
    }

    /** Sends a message from the environment into an in port of the deployed root component. */
    public final <T> void send(InPort<T> port, T message) {
        if (port.owner() != root) {
            throw new IllegalArgumentException("the environment can only send to in ports of the deployed root; " + port + " is not one");
        }
        if (port.owner() instanceof ComposedComponent && port.name().equals(ComposedComponent.FAULTS)) {
            throw new IllegalArgumentException(port + " is fed by the runtime");
        }
        route(port, message);
    }

    /** Receives faults that no composed component routes. Without a listener they are kept in {@link #unhandledFaults()} and printed. */
    public final void onUnhandledFault(Consumer<ComponentFault> listener) {
        this.faultListener = listener;
    }

    /** Faults nobody handled while no listener was set. */
    public final List<ComponentFault> unhandledFaults() {
        synchronized (unhandled) {
            return List.copyOf(unhandled);
        }
    }

    final <T> void route(Port<T> from, T message) {
        if (message == null) {
            throw new IllegalArgumentException("null message on " + from);
        }
        if (!from.type().isInstance(message)) {
            throw new IllegalArgumentException(message.getClass().getName() + " message does not fit " + from);
        }
        if (from.owner().scheduler() != this) {
            throw new IllegalStateException(from + " belongs to an architecture deployed on another scheduler");
        }
        deliver(from, message);
    }

    private void deliver(Port<?> port, Object message) {
        if (port instanceof OutPort<?> out) {
            notifyObservers(out, message);
            for (Port<?> t : out.targets()) {
                deliver(t, message);
            }
        } else if (!port.type().isInstance(message)) {
            fault(port.owner(), port.name(), message, new IllegalArgumentException(message.getClass().getName() + " message does not fit " + port));
        } else if (port.owner() instanceof AtomicComponent atomic) {
            enqueue(Envelope.message(atomic, (InPort<?>) port, message));
        } else if (port.targets().isEmpty()) {
            fault(port.owner(), port.name(), message, new IllegalStateException(port + " is not connected to any subcomponent"));
        } else {
            for (Port<?> t : port.targets()) {
                deliver(t, message);
            }
        }
    }

    @SuppressWarnings("unchecked")
    private static <T> void notifyObservers(OutPort<T> out, Object message) {
        for (Consumer<? super T> o : out.observers()) {
            o.accept((T) message);
        }
    }

    /**
     * Reports a fault of {@code origin}: to the {@code faults} port of the nearest enclosing composed
     * component that connects it, else to the listener. A fault raised while handling a fault goes
     * straight to the listener, so a faulty fault handler cannot loop.
     */
    final void fault(Component origin, String port, Object message, Throwable cause) {
        ComponentFault f = new ComponentFault(origin.path(), port, message, cause);
        if (!(message instanceof ComponentFault)) {
            Optional<ComposedComponent> c = origin.parent();
            while (c.isPresent()) {
                ComposedComponent composed = c.get();
                if (!composed.faults.targets().isEmpty()) {
                    deliver(composed.faults, f);
                    return;
                }
                c = composed.parent();
            }
        }
        unhandled(f);
    }

    private void unhandled(ComponentFault f) {
        Consumer<ComponentFault> l = faultListener;
        if (l != null) {
            try {
                l.accept(f);
                return;
            } catch (RuntimeException e) {
                System.err.println("fault listener threw " + e + " on " + f);
            }
        }
        synchronized (unhandled) {
            unhandled.add(f);
        }
        System.err.println("unhandled " + f);
    }

    abstract void enqueue(Envelope envelope);

    abstract void startActivity(Activity<?> activity);

    @Override
    public void close() {
    }
}
