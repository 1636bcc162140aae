package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * The battery hospital of {@link NumericHospitalBenchmark} planned goal by goal as RefArc plans it: each
 * plan valid and as short in metres as an exact Dijkstra over (place, charge, phase) says is possible,
 * found with little work (a count of states, not a time: the same on any machine and under any load).
 */
class NumericHospitalPlanningTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(120);
    private static final Domain DOMAIN = PddlParser.parseDomain(NumericHospitalBenchmark.DOMAIN, "hospital.pddl");

    private static void plansOptimally(NumericHospitalBenchmark.MapGrid m, NumericHospitalBenchmark.Goal g, long workBound) {
        Problem p = PddlParser.parseProblem(NumericHospitalBenchmark.problem(m, g), "hospital-" + m.n() + ".pddl");
        SolveResult r = new TriadEngine().solve(DOMAIN, p, TIMEOUT);
        int optimal = NumericHospitalBenchmark.optimal(m, g);
        if (optimal < 0) {
            assertEquals(SolveResult.Status.UNSOLVABLE, r.status(), g + ": " + r.message());
            return;
        }
        assertEquals(SolveResult.Status.SOLVED, r.status(), g + ": " + r.message());
        PlanValidator.Report v = PlanValidator.validate(DOMAIN, p, r.plan());
        assertTrue(v.valid(), v.message());
        assertEquals(optimal, PlanValidator.metricValue(DOMAIN, p, r.plan()).orElseThrow(), 1e-9, g + "\n" + r.plan().toPddl());
        assertTrue(r.stats().evaluated() <= workBound, g + ": " + r.stats());
    }

    @Test
    void routesAndDeliveriesWithRechargesAreShortestInMetres() {
        NumericHospitalBenchmark.MapGrid m = NumericHospitalBenchmark.MapGrid.of(36, 4);
        Random rnd = new Random(22);
        for (int i = 0; i < 12; i++) {
            // low charges force recharges on the way; every third goal a delivery with the payload limit
            int start = rnd.nextInt(36);
            NumericHospitalBenchmark.Goal g = new NumericHospitalBenchmark.Goal("goal " + i, start, 8 + rnd.nextInt(40), i % 3 == 0 ? rnd.nextInt(36) : -1,
                    rnd.nextInt(36));
            plansOptimally(m, g, 20_000);
        }
    }

    @Test
    void theBenchmarksHundredWaypointGoalsTakeAFewHundredStates() {
        NumericHospitalBenchmark.MapGrid m = NumericHospitalBenchmark.MapGrid.of(100, 122);
        plansOptimally(m, new NumericHospitalBenchmark.Goal("IsAt(far corner), battery 30", 0, 30, -1, 99), 2_000);
        plansOptimally(m, new NumericHospitalBenchmark.Goal("Delivered(box, room)", 0, 40, 55, 96), 2_000);
    }
}
