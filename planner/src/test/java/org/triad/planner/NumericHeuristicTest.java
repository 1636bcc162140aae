package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.BitSet;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * The search's fact-triggered relaxed graph ({@link NumericHeuristic#estimate}) against the graph as
 * Metric-FF defines it, every operator in every layer ({@link NumericHeuristic#estimateByLayers}): the
 * same estimate in every state tried, dead ends included.
 */
class NumericHeuristicTest {

    private static void assertSameEstimates(Domain d, String text, String label) {
        Problem p = PddlParser.parseProblem(text, label);
        NumericTask task = new NumericTask(d, p);
        NumericHeuristic h = new NumericHeuristic(task);
        BitSet facts = new BitSet();
        task.initFacts.forEach(facts::set);
        assertEquals(h.estimateByLayers(facts, task.initValues), h.estimate(facts, task.initValues), label);
    }

    @Test
    void batteryStatesGetTheReferenceEstimate() {
        Domain d = TestProblems.domain("numeric/battery-domain.pddl");
        String text = TestProblems.text("numeric/battery-problem.pddl");
        for (int battery : new int[] { 0, 4, 5, 10, 25, 30, 45, 60, 70, 100 }) {
            for (String at : new String[] { "lobby", "dock", "c1", "ward" }) {
                assertSameEstimates(d, text.replace("(= (battery r1) 30)", "(= (battery r1) " + battery + ")")
                        .replace("(at r1 lobby)", "(at r1 " + at + ")"), "b" + battery + at + ".pddl");
            }
        }
    }

    @Test
    void counterStatesGetTheReferenceEstimate() {
        Domain d = TestProblems.domain("numeric/counters-domain.pddl");
        String text = TestProblems.text("numeric/counters-problem.pddl");
        Random rnd = new Random(7);
        for (int i = 0; i < 40; i++) {
            int max = 1 + rnd.nextInt(9);
            assertSameEstimates(d, text.replace("(= (max-int) 8)", "(= (max-int) " + max + ")")
                    .replace("(= (value c0) 6)", "(= (value c0) " + rnd.nextInt(10) + ")").replace("(= (value c1) 3)", "(= (value c1) " + rnd.nextInt(10) + ")")
                    .replace("(= (value c2) 0)", "(= (value c2) " + rnd.nextInt(10) + ")"), "c" + i + ".pddl");
        }
    }

    @Test
    void hospitalStatesGetTheReferenceEstimate() {
        Domain d = PddlParser.parseDomain(NumericHospitalBenchmark.DOMAIN, "hospital.pddl");
        NumericHospitalBenchmark.MapGrid m = NumericHospitalBenchmark.MapGrid.of(30, 5);
        Random rnd = new Random(11);
        for (int i = 0; i < 30; i++) {
            // from far too little charge to a full battery, with and without a box to fetch
            NumericHospitalBenchmark.Goal g = new NumericHospitalBenchmark.Goal("g" + i, rnd.nextInt(30), rnd.nextInt(61), i % 2 == 0 ? -1 : rnd.nextInt(30),
                    rnd.nextInt(30));
            assertSameEstimates(d, NumericHospitalBenchmark.problem(m, g), "h" + i + ".pddl");
        }
    }
}
