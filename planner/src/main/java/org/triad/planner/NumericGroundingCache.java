package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Keeps numeric groundings ({@link NumericTask}) so that successive goals of a robot pay only for
 * search, as {@link GroundedProblemCache} does for classical ones. A grounding is reused for a problem
 * with the same domain, objects, static facts, values of the fluents no action changes (a distance
 * table), the same set of changed fluents that have a value (which instances can ever apply depends on
 * it, not on the values: a battery at 25 % or at 100 % grounds alike) and the same metric. Least recently
 * used entries beyond {@code capacity} are dropped. Thread-safe; the cached groundings are only read.
 */
final class NumericGroundingCache {
    /** Everything grounding reads from the domain and the problem. */
    private record Key(Domain domain, List<TypedName> objects, Set<Formula.Atom> statics, Map<String, Double> fixed, Set<String> valued,
            String metric) {
        /** Identity first: a robot's planner hands in the same domain object goal after goal. */
        boolean matches(Key k) {
            return (domain == k.domain || domain.equals(k.domain)) && objects.equals(k.objects) && statics.equals(k.statics) && fixed.equals(k.fixed)
                    && valued.equals(k.valued) && Objects.equals(metric, k.metric);
        }
    }

    private record Entry(Key key, NumericTask grounded) { }

    private final int capacity;
    /** Most recently used last. */
    private final List<Entry> entries = new ArrayList<>();
    private int groundings;
    private int hits;

    NumericGroundingCache(int capacity) {
        if (capacity < 1) throw new IllegalArgumentException("capacity " + capacity);
        this.capacity = capacity;
    }

    /**
     * The task for this problem: grounded once per {@link Key}, the initial state, goal and metric the
     * problem's own. Throws what grounding throws (a {@link PlanningInputException} for a bad problem).
     */
    NumericTask task(Domain domain, Problem problem) {
        Key key = key(domain, problem);
        NumericTask grounded = null;
        synchronized (this) {
            for (int i = entries.size() - 1; i >= 0; i--) {
                Entry e = entries.get(i);
                if (e.key.matches(key)) {
                    entries.remove(i);
                    entries.add(e);
                    grounded = e.grounded;
                    hits++;
                    break;
                }
            }
        }
        if (grounded != null) return new NumericTask(grounded, problem);
        NumericTask task = new NumericTask(domain, problem);
        task.opShapes = NumericDominatedOps.Shapes.of(task);
        synchronized (this) {
            groundings++;
            entries.add(new Entry(key, task));
            if (entries.size() > capacity) entries.remove(0);
        }
        // the cached one is the template: the caller's copy may have its dominated instances set (leftOut)
        return new NumericTask(task, problem);
    }

    /** Groundings computed (misses). */
    synchronized int groundings() {
        return groundings;
    }

    synchronized int hits() {
        return hits;
    }

    private static Key key(Domain domain, Problem problem) {
        Set<String> predicates = new HashSet<>();
        Set<String> functions = new HashSet<>();
        NumericTask.changes(domain, predicates, functions, new HashSet<>());
        Set<Formula.Atom> statics = new HashSet<>();
        for (Formula.Atom a : problem.init()) if (!predicates.contains(a.predicate())) statics.add(a);
        Map<String, Double> fixed = new HashMap<>();
        Set<String> valued = new HashSet<>();
        for (Problem.NumericFact f : problem.numericInit()) {
            String k = NumericValues.key(f.function(), f.args());
            if (functions.contains(f.function())) valued.add(k);
            else fixed.put(k, f.value());
        }
        return new Key(domain, problem.objects(), statics, fixed, valued, problem.metric());
    }
}
