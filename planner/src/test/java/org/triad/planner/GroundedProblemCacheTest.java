package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.Problem;

class GroundedProblemCacheTest {
    private final Domain domain = TestProblems.domain("hospital/domain.pddl");
    private final Problem base = TestProblems.problem("hospital/p-10-b.pddl");

    private Problem withInit(List<Formula.Atom> init) {
        return base.with(init, Formula.Atom.of("item-at", "i0", "r1"));
    }

    @Test
    void staticFactsAreComparedAsASet() {
        GroundedProblemCache cache = new GroundedProblemCache(4);
        GroundedProblem first = cache.get(domain, base);
        List<Formula.Atom> reordered = new ArrayList<>(base.init());
        Collections.reverse(reordered);
        reordered.add(reordered.get(0)); // a repeated fact changes nothing
        assertSame(first, cache.get(domain, withInit(reordered)));
        assertEquals(1, cache.groundings());
        assertEquals(1, cache.hits());
    }

    @Test
    void aMissingStaticFactMasksNoDifferenceEvenWithRepeats() {
        GroundedProblemCache cache = new GroundedProblemCache(4);
        cache.get(domain, base);
        // same number of static facts, one replaced by a repeat of another: a different set
        List<Formula.Atom> init = new ArrayList<>(base.init());
        int adj = -1;
        for (int i = 0; i < init.size(); i++) if (init.get(i).predicate().equals("adj")) adj = i;
        Formula.Atom repeated = init.stream().filter(a -> a.predicate().equals("adj")).findFirst().orElseThrow();
        init.set(adj, repeated);
        cache.get(domain, withInit(init));
        assertEquals(2, cache.groundings());
    }

    @Test
    void leastRecentlyUsedEntriesAreDropped() {
        GroundedProblemCache cache = new GroundedProblemCache(1);
        cache.get(domain, base);
        List<Formula.Atom> more = new ArrayList<>(base.init());
        more.add(Formula.Atom.of("adj", "r1", "r2"));
        cache.get(domain, withInit(more));
        cache.get(domain, base);
        assertEquals(3, cache.groundings());
    }
}
