package org.triad.runtime.component;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A clock for architectures of {@link TimedComponent}s (MontiArc's time-synchronous semantics). One
 * {@link #tick()} is one time slice: what delayed ports held back is delivered, then every timed
 * component computes once, senders before their receivers, each one's messages delivered before
 * the next computes. Components that send to each other without a delayed port in between form a
 * feedback loop no order can serve; {@link #deploy} refuses it, naming the loop. Event-driven
 * components in the same architecture handle their messages as they arrive. Runs on one thread, on
 * a {@link DeterministicScheduler}.
 */
public final class TimeSlices {
    private final DeterministicScheduler scheduler;
    private final List<TimedComponent> order;
    private boolean initialized;
    private long slice;

    private TimeSlices(DeterministicScheduler scheduler, List<TimedComponent> order) {
        this.scheduler = scheduler;
        this.order = order;
    }

    /** Deploys the root on a new deterministic scheduler and orders its timed components. */
    public static TimeSlices deploy(Component root) {
        List<TimedComponent> timed = new ArrayList<>();
        collect(root, timed);
        List<TimedComponent> order = order(timed);
        DeterministicScheduler s = Scheduler.deterministic();
        s.deploy(root);
        return new TimeSlices(s, order);
    }

    public DeterministicScheduler scheduler() {
        return scheduler;
    }

    /** The number of slices run so far. */
    public long slice() {
        return slice;
    }

    /** The order in which the timed components compute within a slice (paths). */
    public List<String> order() {
        return order.stream().map(Component::path).toList();
    }

    /** Queues a message from the environment at an in port of the root, for the next slice. */
    public <T> void send(InPort<T> port, T message) {
        scheduler.send(port, message);
    }

    /** Runs one time slice. */
    public void tick() {
        if (!initialized) {
            initialized = true;
            for (TimedComponent c : order) {
                c.step("initialize", c::initialize);
                scheduler.runUntilIdle();
            }
        }
        for (TimedComponent c : order) {
            c.release();
        }
        scheduler.runUntilIdle();
        for (TimedComponent c : order) {
            c.step("compute", c::compute);
            scheduler.runUntilIdle();
        }
        slice++;
    }

    private static void collect(Component c, List<TimedComponent> into) {
        if (c instanceof TimedComponent t) {
            into.add(t);
        } else if (c instanceof ComposedComponent composed) {
            for (Component sub : composed.subcomponents()) {
                collect(sub, into);
            }
        }
    }

    /** Senders before receivers over connections without a delay (Kahn's algorithm, model order among equals). */
    private static List<TimedComponent> order(List<TimedComponent> timed) {
        Map<TimedComponent, Set<TimedComponent>> receivers = new LinkedHashMap<>();
        Map<TimedComponent, Integer> senders = new HashMap<>();
        for (TimedComponent c : timed) {
            senders.putIfAbsent(c, 0);
        }
        for (TimedComponent c : timed) {
            Set<TimedComponent> rs = new LinkedHashSet<>();
            for (Port<?> p : c.ports()) {
                if (p instanceof OutPort<?> out && !c.isDelayed(out)) {
                    reach(out, rs);
                }
            }
            rs.retainAll(senders.keySet());
            receivers.put(c, rs);
            for (TimedComponent r : rs) {
                senders.merge(r, 1, Integer::sum);
            }
        }
        List<TimedComponent> result = new ArrayList<>();
        Deque<TimedComponent> ready = new ArrayDeque<>();
        for (TimedComponent c : timed) {
            if (senders.get(c) == 0) {
                ready.add(c);
            }
        }
        while (!ready.isEmpty()) {
            TimedComponent c = ready.poll();
            result.add(c);
            for (TimedComponent r : receivers.get(c)) {
                if (senders.merge(r, -1, Integer::sum) == 0) {
                    ready.add(r);
                }
            }
        }
        if (result.size() < timed.size()) {
            List<String> loop = timed.stream().filter(c -> !result.contains(c)).map(Component::path).toList();
            throw new IllegalStateException("feedback loop without a delayed port among " + loop
                    + ": each waits for the others within one time slice; make an out port on the loop <<delayed>>");
        }
        return result;
    }

    /** The timed components an out port's messages reach within the slice, through composed components' ports. */
    private static void reach(Port<?> port, Set<TimedComponent> into) {
        for (Port<?> t : port.targets()) {
            if (t.owner() instanceof TimedComponent tc && t instanceof InPort) {
                into.add(tc);
            } else {
                reach(t, into);
            }
        }
    }
}
