package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/** The applicability tests: triggered by a rare precondition, the same operators, the same work counted. */
class SuccessorsTest {
    /**
     * Over the first 100 states of sokoban p07 (breadth first): the applicable operators are exactly those
     * a test of every operator finds, and the work counted per call is what it was when an operator's
     * first precondition triggered its test (every budget, hence every plan, depends on it).
     */
    @Test
    void aRarePreconditionTriggersTheTestsWithoutChangingTheOperatorsOrTheWork() {
        Domain d = TestProblems.domain("ipc/sokoban-sat11-strips/domain.pddl");
        Problem p = TestProblems.problem("ipc/sokoban-sat11-strips/p07.pddl");
        GroundedProblem.Query q = new GroundedProblem(d, p).query(p);
        SearchTask t = q.task();
        Successors s = new Successors(t);
        int fewerTriggered = 0;
        for (int f = 0; f < t.numFacts; f++) fewerTriggered += Math.max(0, t.firstPreCount[f] - t.triggeredBy[f].length);
        assertTrue(fewerTriggered > 0, "some operator is triggered by another precondition than its first");
        ArrayDeque<int[]> queue = new ArrayDeque<>(List.of(q.init()));
        Set<List<Integer>> seen = new HashSet<>();
        int states = 0;
        while (!queue.isEmpty() && states < 100) {
            int[] state = queue.poll();
            if (!seen.add(Arrays.stream(state).boxed().toList())) continue;
            states++;
            long before = s.work();
            int n = s.applicable(state);
            long counted = t.noPre.length;
            for (int f : state) counted += t.firstPreCount[f];
            assertEquals(counted, s.work() - before);
            int[] found = new int[n];
            for (int i = 0; i < n; i++) found[i] = s.get(i);
            List<Integer> expected = new ArrayList<>();
            for (int o = 0; o < t.ops.length; o++) if (s.isApplicable(state, o)) expected.add(o);
            assertArrayEquals(expected.stream().mapToInt(Integer::intValue).toArray(), found);
            for (int o : found) queue.add(s.apply(state, o));
        }
        assertEquals(100, states);
    }
}
