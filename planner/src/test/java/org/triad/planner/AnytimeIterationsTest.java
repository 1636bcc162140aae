package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * LAMA's later iterations: lazy weighted A* with the FF heuristic and the landmark count, pruned at the
 * best plan's length. A greedy plan's length depends on how its search breaks ties (sokoban-sat11 p07:
 * 83 to 117 steps over 13 operator orders); the plan neighbourhoods cannot leave the local optimum it
 * lands in (89 steps), a search of the whole space below that length can (84; Fast Downward's
 * lama-first 77). Every bound is work, so the lengths asserted are the same on any machine.
 */
class AnytimeIterationsTest {
    private static final Domain SOKOBAN = TestProblems.domain("ipc/sokoban-sat11-strips/domain.pddl");
    private static final Problem SOKOBAN_P07 = TestProblems.problem("ipc/sokoban-sat11-strips/p07.pddl");

    private static long deadline() {
        return System.nanoTime() + Duration.ofMinutes(2).toNanos();
    }

    @Test
    void weightedSearchFindsAPlanShorterThanItsBound() {
        GroundedProblem.Query q = new GroundedProblem(SOKOBAN, SOKOBAN_P07).query(SOKOBAN_P07);
        SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
        long deadline = deadline();
        BestFirstSearch.Result r = new LazyGreedySearch(new FfHeuristic(task), new Landmarks(task, q.init(), q.goalPos(), deadline),
                new Successors(task), deadline).weighted(5, 89).run(q.init(), q.goalPos(), q.goalNeg());
        assertEquals(BestFirstSearch.Outcome.FOUND, r.outcome());
        assertEquals(84, r.plan().length);
        assertTrue(PlanValidator.validate(SOKOBAN, SOKOBAN_P07, pddl(task, r.plan())).valid());
    }

    @Test
    void exhaustingTheBoundProvesThatNoShorterPlanExists() {
        Problem p = LandmarksTest.gripper(2);
        Domain d = TestProblems.domain("ipc/gripper/domain.pddl");
        GroundedProblem.Query q = new GroundedProblem(d, p).query(p);
        SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
        long deadline = deadline();
        Landmarks lms = new Landmarks(task, q.init(), q.goalPos(), deadline);
        // two balls: pick, pick, move, drop, drop
        BestFirstSearch.Result five = new LazyGreedySearch(new FfHeuristic(task), lms, new Successors(task), deadline)
                .weighted(1, 5).run(q.init(), q.goalPos(), q.goalNeg());
        assertEquals(BestFirstSearch.Outcome.EXHAUSTED, five.outcome());
        BestFirstSearch.Result six = new LazyGreedySearch(new FfHeuristic(task), lms, new Successors(task), deadline)
                .weighted(1, 6).run(q.init(), q.goalPos(), q.goalNeg());
        assertEquals(BestFirstSearch.Outcome.FOUND, six.outcome());
        assertEquals(5, six.plan().length);
    }

    /**
     * The improver on LAMA's greedy plan (91 steps) with the budget the engine gives it: 89 after its
     * steps, 84 with the iterations on as much work again.
     */
    @Test
    void theIterationsTakeTheImproverBelowTheGreedyPlansLocalOptimum() {
        GroundedProblem.Query q = new GroundedProblem(SOKOBAN, SOKOBAN_P07).query(SOKOBAN_P07);
        SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
        long deadline = deadline();
        int[] greedy = new LazyGreedySearch(new FfHeuristic(task), new Landmarks(task, q.init(), q.goalPos(), deadline),
                new Successors(task), deadline).run(q.init(), q.goalPos(), q.goalNeg()).plan();
        assertEquals(91, greedy.length);
        long budget = 49_592_924; // the engine's improvement budget for this plan
        int[] without = new PlanImprover(task, new FfHeuristic(task), new Successors(task), deadline, new long[2], 60 * 91, budget)
                .improve(q.init(), q.goalPos(), q.goalNeg(), greedy, false, true);
        PlanImprover improver = new PlanImprover(task, new FfHeuristic(task), new Successors(task), deadline, new long[2], 60 * 91, budget)
                .anytime(budget);
        int[] with = improver.improve(q.init(), q.goalPos(), q.goalNeg(), greedy, false, true);
        assertEquals(89, without.length);
        assertEquals(84, with.length);
        assertTrue(improver.anytimeUsed() <= budget + budget / 10, "the iterations keep to their work: " + improver.anytimeUsed());
        assertTrue(PlanValidator.validate(SOKOBAN, SOKOBAN_P07, pddl(task, with)).valid());
    }

    /**
     * The iterations stop where their work ends, not their time: beside a CPU load a search cut at a
     * work bound has evaluated exactly the states it evaluates on an idle machine, and goes on to the
     * same plan.
     */
    @Test
    void aSearchCutByWorkStopsAtTheSameStateUnderCpuLoad() throws InterruptedException {
        long[] idle = cutThenFinish();
        long[] loaded;
        try (CpuLoad load = CpuLoad.start()) {
            loaded = cutThenFinish();
        }
        assertEquals(84, idle[2]);
        assertEquals(java.util.Arrays.toString(idle), java.util.Arrays.toString(loaded));
    }

    /** Evaluations at the cut (20 M work units), evaluations at the plan, its length. */
    private static long[] cutThenFinish() {
        GroundedProblem.Query q = new GroundedProblem(SOKOBAN, SOKOBAN_P07).query(SOKOBAN_P07);
        SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
        long deadline = deadline();
        FfHeuristic h = new FfHeuristic(task);
        Successors succ = new Successors(task);
        WorkMeter meter = new WorkMeter(h, succ);
        LazyGreedySearch.Run run = new LazyGreedySearch(h, new Landmarks(task, q.init(), q.goalPos(), deadline), succ, deadline)
                .weighted(5, 89).start(q.init(), q.goalPos(), q.goalNeg());
        BestFirstSearch.Result cut = run.resume(meter, meter.now() + 20_000_000, Long.MAX_VALUE);
        assertEquals(BestFirstSearch.Outcome.LIMIT, cut.outcome());
        BestFirstSearch.Result done = run.resume(meter, Long.MAX_VALUE, Long.MAX_VALUE);
        assertEquals(BestFirstSearch.Outcome.FOUND, done.outcome());
        return new long[] {cut.evaluated(), done.evaluated(), done.plan().length};
    }

    private static PddlPlan pddl(SearchTask task, int[] plan) {
        List<PddlStep> steps = new ArrayList<>();
        for (int o : plan) steps.add(task.ops[o].toAction());
        return new PddlPlan(steps);
    }
}
