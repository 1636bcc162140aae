package org.triad.building.traffic;

import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

/** Cycle search in a wait-for graph, for the tests (independent of the table's own). */
final class Graphs {
    private Graphs() {
    }

    /** The robots on some cycle of {@code g}, or empty. */
    static Set<String> cycle(Map<String, Set<String>> g) {
        Set<String> done = new HashSet<>();
        for (String start : g.keySet()) {
            Set<String> path = new LinkedHashSet<>();
            Set<String> c = visit(g, start, path, done);
            if (!c.isEmpty()) {
                return c;
            }
        }
        return Set.of();
    }

    private static Set<String> visit(Map<String, Set<String>> g, String at, Set<String> path, Set<String> done) {
        if (path.contains(at)) {
            return path;
        }
        if (!done.add(at)) {
            return Set.of();
        }
        path.add(at);
        for (String next : g.getOrDefault(at, Set.of())) {
            Set<String> c = visit(g, next, path, done);
            if (!c.isEmpty()) {
                return c;
            }
        }
        path.remove(at);
        return Set.of();
    }
}
