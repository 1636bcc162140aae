package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * The same input gives the same plan however busy the machine is: every budget that decides the plan
 * counts work, not time. No timing is asserted; the load only changes how long each run takes.
 */
class DeterministicPlansTest {
    /** Generous: the runs must not reach it even on a loaded CI machine (then the plan would be "best so far"). */
    private static final Duration TIMEOUT = Duration.ofMinutes(5);

    @Test
    void tenRunsUnderParallelCpuLoadGiveTheIdlePlan() throws InterruptedException {
        // logistics: the goal agenda's plan goes through the improver (lazy search, neighbourhoods,
        // restarts), whose time budget once made its length depend on the load
        assertSamePlanUnderLoad("ipc/logistics00/domain.pddl", "ipc/logistics00/problogistics-10-0.pddl", 8);
    }

    @Test
    void thePortfolioGivesTheSamePlanUnderLoad() throws InterruptedException {
        // negative goals: the first plan comes from the portfolio's turns (slices of work) on the
        // compiled task, then the improver
        assertSamePlanUnderLoad(FirstPlanPortfolioTest.GATES, FirstPlanPortfolioTest.THREE_GATES, 10);
    }

    private static void assertSamePlanUnderLoad(String domainPath, String problemPath, int loadedRuns) throws InterruptedException {
        assertSamePlanUnderLoad(TestProblems.domain(domainPath), TestProblems.problem(problemPath), loadedRuns);
    }

    private static void assertSamePlanUnderLoad(Domain d, Problem p, int loadedRuns) throws InterruptedException {
        String idle = solve(d, p);
        List<String> loaded = new ArrayList<>();
        try (CpuLoad load = CpuLoad.start()) {
            for (int i = 0; i < loadedRuns; i++) loaded.add(solve(d, p));
        }
        for (String plan : loaded) assertEquals(idle, plan, p.name() + ": a loaded run's plan differs from the idle run's");
    }

    /** A fresh engine each time, as a fresh process would have. */
    private static String solve(Domain d, Problem p) {
        SolveResult r = new TriadEngine(new GroundedProblemCache(1)).solve(d, p, TIMEOUT);
        assertTrue(r.isSolved(), r.status() + " " + r.message());
        assertFalse(r.isBestSoFar(), "the timeout cut improvement short");
        assertTrue(PlanValidator.validate(d, p, r.plan()).valid());
        return r.plan().toPddl();
    }
}
