package org.triad.runtime.planning;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.runtime.pddl.Action;
import org.triad.runtime.pddl.Domain;
import org.triad.runtime.pddl.Effect;
import org.triad.runtime.pddl.Formula;
import org.triad.runtime.pddl.Problem;
import org.triad.runtime.pddl.TypedName;

/**
 * Keeps groundings keyed by domain, objects, static facts and numeric facts, so successive goals
 * of a task pay only for search. Least recently used entries beyond {@code capacity} are dropped.
 */
public final class GroundedProblemCache {
    private record Key(Domain domain, List<TypedName> objects, Set<Formula.Atom> staticFacts, List<Problem.NumericFact> numeric) { }

    private final int capacity;
    private final Map<Key, GroundedProblem> entries;
    private final Map<Domain, Set<String>> fluentPredicates = new LinkedHashMap<>();
    private int groundings;
    private int hits;

    public GroundedProblemCache(int capacity) {
        this.capacity = capacity;
        this.entries = new LinkedHashMap<>(16, 0.75f, true);
    }

    /** The grounding for this problem, computed at most once per key. */
    public synchronized GroundedProblem get(Domain domain, Problem problem) {
        Set<String> fluents = fluentPredicates.computeIfAbsent(domain, GroundedProblemCache::fluents);
        Set<Formula.Atom> statics = new HashSet<>();
        for (Formula.Atom a : problem.init()) if (!fluents.contains(a.predicate())) statics.add(a);
        Key key = new Key(domain, problem.objects(), statics, problem.numericInit());
        GroundedProblem g = entries.get(key);
        if (g != null) {
            hits++;
            return g;
        }
        g = new GroundedProblem(domain, problem);
        groundings++;
        entries.put(key, g);
        if (entries.size() > capacity) entries.remove(entries.keySet().iterator().next());
        if (fluentPredicates.size() > capacity) fluentPredicates.remove(fluentPredicates.keySet().iterator().next());
        return g;
    }

    /** Full groundings computed (cache misses). */
    public synchronized int groundings() {
        return groundings;
    }

    public synchronized int hits() {
        return hits;
    }

    static Set<String> fluents(Domain domain) {
        Set<String> out = new HashSet<>();
        for (Action a : domain.actions()) {
            List<Formula.Atom> atoms = new ArrayList<>();
            collect(a.effects(), atoms);
            atoms.forEach(x -> out.add(x.predicate()));
        }
        return out;
    }

    private static void collect(List<Effect> effects, List<Formula.Atom> out) {
        for (Effect e : effects) {
            if (e instanceof Effect.Add x) out.add(x.atom());
            else if (e instanceof Effect.Delete x) out.add(x.atom());
            else if (e instanceof Effect.Forall x) collect(x.body(), out);
        }
    }

}
