package org.triad.vda5050.mqtt;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Listens to every VDA 5050 topic on a broker ({@code uagv/#}) and checks each message against the official
 * schemas: what the tests use to show that every message either side sent conformed.
 */
public final class ConformanceMonitor implements AutoCloseable {
    private final MqttLink link;
    private final List<String> violations = new ArrayList<>();
    private final Map<String, Integer> counts = new TreeMap<>();

    private ConformanceMonitor(String broker) {
        this.link = MqttLink.connect(broker, "triad-monitor-" + ProcessHandle.current().pid() + "-" + Long.toHexString(System.nanoTime()), null,
                this::violation, 10, 5);
        link.subscribe("uagv/#", r -> count(r.address().topic().leaf()));
    }

    public static ConformanceMonitor on(String broker) {
        return new ConformanceMonitor(broker);
    }

    private synchronized void violation(String line) {
        violations.add(line);
    }

    private synchronized void count(String leaf) {
        counts.merge(leaf, 1, Integer::sum);
    }

    /** The messages that were not JSON, violated their schema or spoke another major version, one line each. */
    public synchronized List<String> violations() {
        return List.copyOf(violations);
    }

    /** Conforming messages seen, by topic ({@code state}, {@code order}, ...). */
    public synchronized Map<String, Integer> counts() {
        return new TreeMap<>(counts);
    }

    public synchronized int total() {
        return counts.values().stream().mapToInt(Integer::intValue).sum();
    }

    @Override
    public void close() {
        link.close();
    }
}
