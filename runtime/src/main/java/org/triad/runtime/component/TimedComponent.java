package org.triad.runtime.component;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * An atomic component that runs in time slices, as MontiArc's synchronous and timed components do:
 * each slice of a {@link TimeSlices} clock it computes once. Messages arriving at an in port queue
 * up; {@link #poll} takes the next one (a synchronous component takes at most one per port and
 * slice, {@code null} when none came). A message sent on a {@linkplain #delayedOutPort delayed} out
 * port reaches its receivers one slice later, which is what breaks a feedback loop.
 */
public abstract class TimedComponent extends AtomicComponent {
    private final Map<InPort<?>, Deque<Object>> queues = new HashMap<>();
    private final Set<OutPort<?>> delayed = new HashSet<>();
    private final List<Object[]> held = new ArrayList<>();

    /** An out port whose messages reach their receivers in the next time slice. */
    protected final <T> OutPort<T> delayedOutPort(String portName, Class<T> type) {
        OutPort<T> port = outPort(portName, type);
        delayed.add(port);
        return port;
    }

    /** Whether the port's messages arrive one time slice after they are sent. */
    public final boolean isDelayed(OutPort<?> port) {
        return delayed.contains(port);
    }

    /** Runs once before the first time slice: the init block and the initial actions of an automaton. */
    protected void initialize() throws Exception {
    }

    /** One time slice: reads the in ports ({@link #poll}) and sends on the out ports ({@link #emit}). */
    protected abstract void compute() throws Exception;

    /** The next message queued at the port, or null if none is left. */
    @SuppressWarnings("unchecked")
    protected final <T> T poll(InPort<T> port) {
        Deque<Object> q = queues.get(port);
        return q == null ? null : (T) q.poll();
    }

    /** Sends a message: now, or in the next slice on a delayed port. A null value sends nothing (an absent message). */
    protected final <T> void emit(OutPort<T> port, T value) {
        if (value == null) {
            return;
        }
        if (delayed.contains(port)) {
            held.add(new Object[] { port, value });
        } else {
            port.send(value);
        }
    }

    @Override
    void deployOn(Scheduler s) {
        for (Port<?> p : ports()) {
            if (p instanceof InPort<?> in) {
                Deque<Object> q = new ArrayDeque<>();
                queues.put(in, q);
                on(in, q::add);
            }
        }
        super.deployOn(s);
    }

    /** Sends what the delayed ports held back in the previous slice. */
    @SuppressWarnings("unchecked")
    final void release() {
        List<Object[]> now = new ArrayList<>(held);
        held.clear();
        for (Object[] m : now) {
            ((OutPort<Object>) m[0]).send(m[1]);
        }
    }

    /** Runs a step of this component; what it throws becomes a fault, as for any handler. */
    final void step(String label, Step step) {
        try {
            step.run();
        } catch (Throwable t) {
            scheduler().fault(this, label, null, t);
        }
    }

    interface Step {
        void run() throws Exception;
    }
}
