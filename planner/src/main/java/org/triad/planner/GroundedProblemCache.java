package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Keeps groundings keyed by domain, objects, static facts and numeric facts, so successive goals
 * of a task pay only for search. Least recently used entries beyond {@code capacity} are dropped.
 */
public final class GroundedProblemCache {
    /**
     * A cached grounding and what it was computed for. The static facts are compared as a set but
     * looked up without building one per call: an order-independent hash and count over the
     * problem's static facts select the candidate, then every fact is checked against the entry's
     * index (a warm call on thousands of static facts stays cheap).
     */
    private static final class Entry {
        final Domain domain;
        final List<TypedName> objects;
        final List<Problem.NumericFact> numeric;
        final Map<Formula.Atom, Integer> statics;
        final int staticHash;
        final int staticCount;
        final GroundedProblem grounding;

        Entry(Domain domain, Problem problem, Set<String> fluents, int staticHash, int staticCount) {
            this.domain = domain;
            this.objects = problem.objects();
            this.numeric = problem.numericInit();
            this.statics = new HashMap<>();
            for (Formula.Atom a : problem.init()) {
                if (!fluents.contains(a.predicate())) statics.putIfAbsent(a, statics.size());
            }
            this.staticHash = staticHash;
            this.staticCount = staticCount;
            this.grounding = new GroundedProblem(domain, problem);
        }

        /** With {@code quick}, only candidates of equal hash and count (repeated facts make them differ). */
        boolean matches(Domain d, Problem p, Set<String> fluents, int hash, int count, boolean quick) {
            if (quick && (hash != staticHash || count != staticCount)) return false;
            if (d != domain && !d.equals(domain)) return false;
            if (p.objects() != objects && !p.objects().equals(objects)) return false;
            if (p.numericInit() != numeric && !p.numericInit().equals(numeric)) return false;
            boolean[] seen = new boolean[statics.size()];
            int distinct = 0;
            for (Formula.Atom a : p.init()) {
                if (fluents.contains(a.predicate())) continue;
                Integer i = statics.get(a);
                if (i == null) return false;
                if (!seen[i]) { seen[i] = true; distinct++; }
            }
            return distinct == seen.length;
        }
    }

    private final int capacity;
    /** Most recently used last. */
    private final List<Entry> entries = new ArrayList<>();
    private final Map<Domain, Set<String>> fluentPredicates = new LinkedHashMap<>();
    private int groundings;
    private int hits;

    public GroundedProblemCache(int capacity) {
        this.capacity = capacity;
    }

    /** The grounding for this problem, computed at most once per domain, objects, static and numeric facts. */
    public synchronized GroundedProblem get(Domain domain, Problem problem) {
        Set<String> fluents = fluentPredicates.computeIfAbsent(domain, GroundedProblemCache::fluents);
        int hash = 0;
        int count = 0;
        for (Formula.Atom a : problem.init()) {
            if (fluents.contains(a.predicate())) continue;
            hash += a.hashCode();
            count++;
        }
        // a miss costs a grounding, so the full set comparison on every entry is cheap beside it
        for (boolean quick : new boolean[] {true, false}) {
            for (int i = entries.size() - 1; i >= 0; i--) {
                Entry e = entries.get(i);
                if (e.grounding.broken()) {
                    entries.remove(i);
                    continue;
                }
                if (e.matches(domain, problem, fluents, hash, count, quick)) {
                    hits++;
                    entries.remove(i);
                    entries.add(e);
                    return e.grounding;
                }
            }
        }
        Entry e = new Entry(domain, problem, fluents, hash, count);
        groundings++;
        entries.add(e);
        if (entries.size() > capacity) entries.remove(0);
        if (fluentPredicates.size() > capacity) fluentPredicates.remove(fluentPredicates.keySet().iterator().next());
        return e.grounding;
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

    private static void collect(List<PddlEffect> effects, List<Formula.Atom> out) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.Add x) out.add(x.atom());
            else if (e instanceof PddlEffect.Delete x) out.add(x.atom());
            else if (e instanceof PddlEffect.Forall x) collect(x.body(), out);
            else if (e instanceof PddlEffect.When x) collect(x.body(), out);
        }
    }

}
