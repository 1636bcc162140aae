package org.triad.runtime.component;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Function;

/** Small components for runtime tests. */
final class TestComponents {
    private TestComponents() {
    }

    /** Applies a function to each integer and sends the result; records what it saw. */
    static final class Mapper extends AtomicComponent {
        final InPort<Integer> in = inPort("in", Integer.class);
        final OutPort<Integer> out = outPort("out", Integer.class);
        final List<Integer> seen = Collections.synchronizedList(new ArrayList<>());

        Mapper(Function<Integer, Integer> f) {
            on(in, m -> {
                seen.add(m);
                out.send(f.apply(m));
            });
        }
    }

    /** Records every message; a message equal to {@code poison} makes the handler throw. */
    static final class Sink<T> extends AtomicComponent {
        final InPort<T> in;
        final List<T> received = Collections.synchronizedList(new ArrayList<>());

        Sink(Class<T> type, T poison) {
            in = inPort("in", type);
            on(in, m -> {
                if (m.equals(poison)) {
                    throw new IllegalStateException("poisoned by " + m);
                }
                received.add(m);
            });
        }

        Sink(Class<T> type) {
            this(type, null);
        }
    }

    /** An atomic component with an in port but no handler for it. */
    static final class Deaf extends AtomicComponent {
        final InPort<String> in = inPort("in", String.class);
    }

    /** Starts an activity per request and sends its result; records the order of events. */
    static final class Worker extends AtomicComponent {
        final InPort<String> request = inPort("request", String.class);
        final InPort<String> ping = inPort("ping", String.class);
        final OutPort<String> done = outPort("done", String.class);
        final List<String> log = Collections.synchronizedList(new ArrayList<>());

        Worker(Function<String, Callable<String>> work) {
            on(request, r -> {
                log.add("start " + r);
                startActivity("work", r, work.apply(r), result -> {
                    log.add("done " + result);
                    done.send(result);
                });
            });
            on(ping, p -> log.add("ping " + p));
        }
    }

    /** Collects faults it receives as messages. */
    static final class FaultCollector extends AtomicComponent {
        final InPort<ComponentFault> in = inPort("in", ComponentFault.class);
        final List<ComponentFault> faults = Collections.synchronizedList(new ArrayList<>());
        boolean throwOnFault;

        FaultCollector() {
            on(in, f -> {
                faults.add(f);
                if (throwOnFault) {
                    throw new IllegalStateException("collector broken");
                }
            });
        }
    }
}
