package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/** The first-plan portfolio and the compilation of negative goals it searches on. */
class FirstPlanPortfolioTest {
    /** Gates to clear in order: clearing one needs the previous one cleared (a negative precondition). */
    static final Domain GATES = PddlParser.parseDomain("""
            (define (domain gates) (:requirements :strips :negative-preconditions)
              (:predicates (pending ?g) (after ?g ?h) (first ?g) (armed))
              (:action arm :parameters () :precondition (not (armed)) :effect (armed))
              (:action clear-first :parameters (?g) :precondition (and (first ?g) (pending ?g) (armed))
                 :effect (and (not (pending ?g)) (not (armed))))
              (:action clear :parameters (?g ?h) :precondition (and (after ?g ?h) (pending ?g) (not (pending ?h)) (armed))
                 :effect (and (not (pending ?g)) (not (armed)))))
            """, "gates.pddl");

    static final Problem THREE_GATES = PddlParser.parseProblem("""
            (define (problem three) (:domain gates) (:objects a b c)
              (:init (pending a) (pending b) (pending c) (first a) (after b a) (after c b))
              (:goal (and (not (pending a)) (not (pending b)) (not (pending c)))))
            """, "three.pddl");

    /** Two doors and one key that the first door keeps: relaxed solvable, really not. */
    private static final Domain DOORS = PddlParser.parseDomain("""
            (define (domain doors) (:requirements :strips)
              (:predicates (has-key) (open ?d) (door ?d) (at ?p) (road ?p ?q))
              (:action move :parameters (?p ?q) :precondition (and (at ?p) (road ?p ?q)) :effect (and (at ?q) (not (at ?p))))
              (:action unlock :parameters (?d) :precondition (and (door ?d) (has-key)) :effect (and (open ?d) (not (has-key)))))
            """, "doors.pddl");

    private static final Problem TWO_DOORS = PddlParser.parseProblem("""
            (define (problem two) (:domain doors) (:objects d1 d2 p q r)
              (:init (has-key) (door d1) (door d2) (at p) (road p q) (road q p) (road q r) (road r q))
              (:goal (and (open d1) (open d2) (at r))))
            """, "two.pddl");

    private static GroundedProblem.Query query(Domain d, Problem p) {
        return new GroundedProblem(d, p).query(p);
    }

    private static long deadline() {
        return System.nanoTime() + 10_000_000_000L;
    }

    @Test
    void negativeGoalsBecomeComplementFactsTheHeuristicCounts() {
        GroundedProblem.Query q = query(GATES, THREE_GATES);
        assertEquals(0, q.goalPos().length);
        assertEquals(3, q.goalNeg().length);
        assertEquals(0, new FfHeuristic(q.task()).evaluate(q.init(), q.goalPos()), "blind without the compilation");

        NegativeGoalCompilation c = NegativeGoalCompilation.of(q.task(), q.init(), q.goalPos(), q.goalNeg());
        assertNotNull(c);
        assertEquals(3, c.goalPos.length);
        assertEquals(q.task().ops.length, c.task.ops.length);
        for (int o = 0; o < c.task.ops.length; o++) assertEquals(0, c.task.neg[o].length, "negative preconditions compiled away");
        // the last gate needs the other two cleared first: three clears and three arms, relaxed
        assertEquals(4, new FfHeuristic(c.task).evaluate(c.init, c.goalPos));
    }

    @Test
    void aPlanOfTheCompiledTaskSolvesTheOriginal() {
        GroundedProblem.Query q = query(GATES, THREE_GATES);
        NegativeGoalCompilation c = NegativeGoalCompilation.of(q.task(), q.init(), q.goalPos(), q.goalNeg());
        long[] effort = new long[2];
        BestFirstSearch.Result r = new FirstPlanPortfolio(c.task, new FfHeuristic(c.task), new Successors(c.task), deadline())
                .run(c.init, c.goalPos, new int[0], effort);
        assertEquals(BestFirstSearch.Outcome.FOUND, r.outcome());
        assertEquals(6, r.plan().length);
        Successors s = new Successors(q.task());
        int[] state = q.init();
        for (int o : r.plan()) {
            assertTrue(s.isApplicable(state, o));
            state = s.apply(state, o);
        }
        assertTrue(Successors.satisfies(state, q.goalPos(), q.goalNeg()));
        assertTrue(effort[1] > 0);
    }

    @Test
    void anInterruptedLazySearchResumesWhereItStopped() {
        GroundedProblem.Query q = query(GATES, THREE_GATES);
        NegativeGoalCompilation c = NegativeGoalCompilation.of(q.task(), q.init(), q.goalPos(), q.goalNeg());
        BestFirstSearch.Result whole = new LazyGreedySearch(new FfHeuristic(c.task), null, new Successors(c.task), deadline())
                .run(c.init, c.goalPos, new int[0]);
        FfHeuristic h = new FfHeuristic(c.task);
        Successors succ = new Successors(c.task);
        WorkMeter meter = new WorkMeter(h, succ);
        LazyGreedySearch.Run run = new LazyGreedySearch(h, null, succ, deadline()).start(c.init, c.goalPos, new int[0]);
        assertEquals(BestFirstSearch.Outcome.LIMIT, run.resume(meter, meter.now() + 1, Long.MAX_VALUE).outcome());
        assertEquals(BestFirstSearch.Outcome.LIMIT, run.resume(meter, meter.now() + 50, Long.MAX_VALUE).outcome());
        BestFirstSearch.Result resumed = run.resume(meter, Long.MAX_VALUE, Long.MAX_VALUE);
        assertEquals(BestFirstSearch.Outcome.FOUND, resumed.outcome());
        org.junit.jupiter.api.Assertions.assertArrayEquals(whole.plan(), resumed.plan());
        assertEquals(whole.evaluated(), resumed.evaluated());
    }

    /**
     * After the portfolio's plan, its other lazy searches go on for a budget of work and the shortest
     * plan is kept: valid, never longer, the same in every run (work, not time); with no budget, or
     * once the searches are released, the plan as it was.
     */
    @Test
    void theOtherSearchesGoOnAndTheShortestPlanIsKept() {
        GroundedProblem.Query q = query(GATES, THREE_GATES);
        NegativeGoalCompilation c = NegativeGoalCompilation.of(q.task(), q.init(), q.goalPos(), q.goalNeg());
        int[][] plans = new int[2][];
        for (int run = 0; run < 2; run++) {
            FirstPlanPortfolio portfolio = new FirstPlanPortfolio(c.task, new FfHeuristic(c.task), new Successors(c.task), deadline());
            long[] effort = new long[2];
            BestFirstSearch.Result first = portfolio.run(c.init, c.goalPos, new int[0], effort);
            assertEquals(BestFirstSearch.Outcome.FOUND, first.outcome());
            assertSame(first.plan(), portfolio.shorterPlan(c.init, c.goalPos, new int[0], first.plan(), 0, effort));
            long evaluated = effort[1];
            int[] plan = portfolio.shorterPlan(c.init, c.goalPos, new int[0], first.plan(), TriadEngine.IMPROVEMENT_CAP, effort);
            assertTrue(effort[1] > evaluated && portfolio.continuedWork() > 0, "the other searches ran");
            assertTrue(plan.length <= first.plan().length);
            Successors s = new Successors(c.task);
            int[] state = c.init;
            for (int o : plan) {
                assertTrue(s.isApplicable(state, o));
                state = s.apply(state, o);
            }
            assertTrue(Successors.satisfies(state, c.goalPos, new int[0]));
            assertSame(plan, portfolio.shorterPlan(c.init, c.goalPos, new int[0], plan, TriadEngine.IMPROVEMENT_CAP, effort), "released");
            plans[run] = plan;
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(plans[0], plans[1]);
    }

    @Test
    void noCompilationWithoutNegativeGoals() {
        GroundedProblem.Query q = query(DOORS, TWO_DOORS);
        assertNull(NegativeGoalCompilation.of(q.task(), q.init(), q.goalPos(), q.goalNeg()));
    }

    @Test
    void exhaustingTheSearchProvesTheTaskUnsolvable() {
        GroundedProblem.Query q = query(DOORS, TWO_DOORS);
        assertTrue(new FfHeuristic(q.task()).evaluate(q.init(), q.goalPos()) < FfHeuristic.INFINITE, "relaxed solvable");
        BestFirstSearch.Result r = new FirstPlanPortfolio(q.task(), new FfHeuristic(q.task()), new Successors(q.task()), deadline())
                .run(q.init(), q.goalPos(), q.goalNeg(), new long[2]);
        assertEquals(BestFirstSearch.Outcome.EXHAUSTED, r.outcome());
    }

    @Test
    void theEngineSolvesNegativeGoalsWithAValidPlan() {
        SolveResult r = new TriadEngine().solve(GATES, THREE_GATES, Duration.ofSeconds(10));
        assertTrue(r.isSolved(), r.message());
        assertEquals(6, r.plan().steps().size());
        assertTrue(PlanValidator.validate(GATES, THREE_GATES, r.plan()).valid());
    }
}
