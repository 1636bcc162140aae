package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

class CompressedGraphSearchTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    private static GroundedProblem.Query query(Domain d, Problem p) {
        return new GroundedProblemCache(1).get(d, p).query(p);
    }

    private static SearchTask relevant(GroundedProblem.Query q) {
        return q.task().relevantTo(q.goalPos(), q.goalNeg());
    }

    private static boolean applies(Domain d, Problem p) {
        GroundedProblem.Query q = query(d, p);
        return CompressedGraphSearch.applies(relevant(q), q.init(), q.goalPos(), q.goalNeg());
    }

    @ParameterizedTest
    @ValueSource(strings = {"p-10-b", "p-50-b", "p-100-b"})
    void hospitalDeliveryIsSolvedOptimallyByTheCompressedSearch(String name) {
        Domain d = TestProblems.domain("hospital/domain.pddl");
        Problem p = TestProblems.problem("hospital/" + name + ".pddl");
        GroundedProblem.Query q = query(d, p);
        SearchTask t = relevant(q);
        assertTrue(CompressedGraphSearch.applies(t, q.init(), q.goalPos(), q.goalNeg()));
        CompressedGraphSearch.Result r = new CompressedGraphSearch(t, new Successors(t), Long.MAX_VALUE, Long.MAX_VALUE)
                .run(q.init(), q.goalPos(), q.goalNeg());
        assertEquals(BestFirstSearch.Outcome.FOUND, r.outcome());
        List<PddlStep> steps = new ArrayList<>();
        for (int o : r.plan()) steps.add(t.ops[o].toAction());
        PlanValidator.Report report = PlanValidator.validate(d, p, new PddlPlan(steps));
        assertTrue(report.valid(), report.message());
        assertEquals(TestProblems.hospitalOptimal().get(name), steps.size());
        assertTrue(r.work() < TriadEngine.GRAPH_SEARCH_WORK / 100, "work " + r.work());
    }

    @Test
    void theWorkBoundStopsTheSearch() {
        Domain d = TestProblems.domain("hospital/domain.pddl");
        Problem p = TestProblems.problem("hospital/p-50-b.pddl");
        GroundedProblem.Query q = query(d, p);
        SearchTask t = relevant(q);
        CompressedGraphSearch.Result r = new CompressedGraphSearch(t, new Successors(t), Long.MAX_VALUE, 10)
                .run(q.init(), q.goalPos(), q.goalNeg());
        assertEquals(BestFirstSearch.Outcome.LIMIT, r.outcome());
    }

    @Test
    void hospitalDeliveryThroughThePlannerIsOptimal() {
        Domain d = TestProblems.domain("hospital/domain.pddl");
        Problem p = TestProblems.problem("hospital/p-100-b.pddl");
        SolveResult r = TriadEngineTest.solveAndValidate(d, p);
        assertEquals(TestProblems.hospitalOptimal().get("p-100-b"), r.plan().length());
        // the compressed search expands only a handful of states (A* with FF expands one per step)
        assertTrue(r.stats().expanded() < 10, "expanded " + r.stats().expanded());
    }

    /** A lift that also changes the robot's place, but only when powered: not a move. */
    private static final String LIFT = """
            (define (domain lift) (:requirements :strips)
              (:predicates (at ?w) (adj ?a ?b) (lift ?a ?b) (powered) (switch ?w) (item-at ?w) (holding))
              (:action move :parameters (?a ?b) :precondition (and (at ?a) (adj ?a ?b))
                :effect (and (at ?b) (not (at ?a))))
              (:action power :parameters (?w) :precondition (and (at ?w) (switch ?w)) :effect (powered))
              (:action ride :parameters (?a ?b) :precondition (and (at ?a) (lift ?a ?b) (powered))
                :effect (and (at ?b) (not (at ?a))))
              (:action load :parameters (?w) :precondition (and (at ?w) (item-at ?w))
                :effect (and (holding) (not (item-at ?w))))
              (:action unload :parameters (?w) :precondition (and (at ?w) (holding))
                :effect (and (item-at ?w) (not (holding)))))
            """;

    private static final String CORRIDOR = "(adj w0 w1) (adj w1 w0) (adj w1 w2) (adj w2 w1) (adj w2 w3) (adj w3 w2) "
            + "(adj w3 w4) (adj w4 w3) (adj w4 w5) (adj w5 w4) (adj w5 w6) (adj w6 w5) ";

    @Test
    void aNonMoveActionChangingThePlaceDisablesTheCompressedSearch() {
        Domain d = PddlParser.parseDomain(LIFT, "lift");
        // walking is 6 steps; power + ride is 2: compressing walks alone would miss the ride
        Problem p = PddlParser.parseProblem("(define (problem p) (:domain lift) (:objects w0 w1 w2 w3 w4 w5 w6)"
                + " (:init (at w0) (switch w0) (lift w0 w6) " + CORRIDOR + ") (:goal (at w6)))", "p");
        assertFalse(applies(d, p));
        assertEquals(2, TriadEngineTest.solveAndValidate(d, p).plan().length());
    }

    @Test
    void withoutTheLiftTheSameDeliveryTakesTheCompressedSearch() {
        Domain d = PddlParser.parseDomain(LIFT, "lift");
        Problem p = PddlParser.parseProblem("(define (problem p) (:domain lift) (:objects w0 w1 w2 w3 w4 w5 w6)"
                + " (:init (at w3) (item-at w0) " + CORRIDOR + ") (:goal (item-at w6)))", "p");
        assertTrue(applies(d, p));
        // 3 moves to w0, load, 6 moves to w6, unload
        assertEquals(11, TriadEngineTest.solveAndValidate(d, p).plan().length());
    }

    @Test
    void twoTokensOnOneGraphDisableTheCompressedSearch() {
        Domain d = PddlParser.parseDomain(LIFT, "lift");
        // two places at once: moves would interact through the shared facts
        Problem p = PddlParser.parseProblem("(define (problem p) (:domain lift) (:objects w0 w1 w2 w3 w4 w5 w6)"
                + " (:init (at w0) (at w6) (item-at w3) " + CORRIDOR + ") (:goal (item-at w5)))", "p");
        assertFalse(applies(d, p));
        TriadEngineTest.solveAndValidate(d, p);
    }

    @Test
    void aGoalThatAPlaceBeFalseDisablesTheCompressedSearch() {
        Domain d = PddlParser.parseDomain(LIFT.replace("(:requirements :strips)", "(:requirements :strips :negative-preconditions)"), "lift");
        Problem p = PddlParser.parseProblem("(define (problem p) (:domain lift) (:objects w0 w1 w2 w3 w4 w5 w6)"
                + " (:init (at w0) (item-at w3) " + CORRIDOR + ") (:goal (and (item-at w5) (not (at w5)))))", "p");
        assertFalse(applies(d, p));
        assertEquals(8, TriadEngineTest.solveAndValidate(d, p).plan().length());
    }

    @Test
    void anUnreachableDeliveryIsProvenUnsolvable() {
        Domain d = PddlParser.parseDomain(LIFT, "lift");
        // one-way corridor: ignoring deletes the robot stays at w0 after fetching the item, really it cannot return
        Problem p = PddlParser.parseProblem("(define (problem p) (:domain lift) (:objects w0 w1 w2)"
                + " (:init (at w0) (item-at w1) (adj w0 w1) (adj w1 w2)) (:goal (item-at w0)))", "p");
        assertTrue(applies(d, p));
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status(), r.message());
    }
}
