package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Inputs an attacker would try: the engine refuses what cannot fit before instantiating it, in one
 * line naming the size, and stops grounding at the timeout. Small sizes that show the estimate; no
 * timing is asserted.
 */
class EngineLimitsTest {
    private static final Duration TIMEOUT = Duration.ofMinutes(2);

    private static String objects(int n) {
        return IntStream.range(0, n).mapToObj(i -> "o" + i).collect(Collectors.joining(" "));
    }

    private static final Domain FREE3 = PddlParser.parseDomain("""
            (define (domain free3) (:requirements :strips :typing) (:types obj)
             (:predicates (done ?a ?b ?c - obj))
             (:action act :parameters (?a ?b ?c - obj) :precondition (and) :effect (done ?a ?b ?c)))
            """, "free3.pddl");

    private static Problem free3(int n) {
        return PddlParser.parseProblem("(define (problem f) (:domain free3) (:objects " + objects(n)
                + " - obj) (:init) (:goal (done o1 o2 o3)))", "free3-problem.pddl");
    }

    @Test
    void aFreeThreeParameterActionOverManyObjectsIsRefusedBeforeGrounding() {
        // 1,000 objects: 10⁹ actions, more than any heap here holds (600 bytes each)
        SolveResult r = new TriadEngine().solve(FREE3, free3(1000), TIMEOUT);
        assertEquals(SolveResult.Status.ERROR, r.status());
        assertTrue(r.message().startsWith("grounding would create 1·10⁹ actions of 'act' (3 parameters no precondition binds, 1,000 objects each)"),
                r.message());
        assertTrue(!r.message().contains("\n"), "one line");
    }

    @Test
    void theSameActionOverFewObjectsIsGroundedAndSolved() {
        SolveResult r = new TriadEngine().solve(FREE3, free3(10), TIMEOUT);
        assertTrue(r.isSolved(), r.message());
        assertEquals(1, r.plan().length());
    }

    @Test
    void anActionOfTwoThousandParametersIsRefusedWithoutRecursingThroughThem() {
        String params = IntStream.range(0, 2000).mapToObj(i -> "?p" + i).collect(Collectors.joining(" "));
        Domain d = PddlParser.parseDomain("(define (domain wide) (:requirements :strips :typing) (:types obj) (:predicates (done ?a - obj))"
                + " (:action act :parameters (" + params + " - obj) :precondition (and) :effect (done ?p0)))", "wide.pddl");
        Problem p = PddlParser.parseProblem("(define (problem w) (:domain wide) (:objects a b c - obj) (:init) (:goal (done a)))", "w.pddl");
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.ERROR, r.status());
        assertTrue(r.message().startsWith("grounding would create 2·10⁹⁵⁴ actions of 'act' (2000 parameters"), r.message());
    }

    @Test
    void aQuantifierOverThreeVariablesAndThousandsOfObjectsIsRefusedBeforeExpanding() {
        Domain d = PddlParser.parseDomain("""
                (define (domain fa) (:requirements :adl :typing) (:types obj)
                 (:predicates (r ?a ?b ?c - obj) (ok))
                 (:action check :parameters () :precondition (forall (?x ?y ?z - obj) (not (r ?x ?y ?z))) :effect (ok)))
                """, "fa.pddl");
        Problem p = PddlParser.parseProblem("(define (problem fa) (:domain fa) (:objects " + objects(2000) + " - obj) (:init) (:goal (ok)))",
                "fa-problem.pddl");
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.ERROR, r.status());
        assertTrue(r.message().startsWith("grounding would create 8·10⁹ bindings of the quantifier over ?x ?y ?z (3 variables over 2,000 objects each)"),
                r.message());
        Problem small = PddlParser.parseProblem("(define (problem fa) (:domain fa) (:objects " + objects(5) + " - obj) (:init) (:goal (ok)))",
                "fa-small.pddl");
        assertTrue(new TriadEngine().solve(d, small, TIMEOUT).isSolved());
    }

    @Test
    void theTimeoutHoldsWhileGroundingAndTheCutShortGroundingIsNotReused() {
        GroundedProblemCache cache = new GroundedProblemCache(2);
        TriadEngine engine = new TriadEngine(cache);
        // 216,000 actions fit the estimate but take far longer than no time at all to ground: a
        // timeout already passed stops grounding at its first clock check
        SolveResult r = engine.solve(FREE3, free3(60), Duration.ZERO);
        assertEquals(SolveResult.Status.TIMEOUT, r.status(), r.message());
        assertEquals("time limit reached while grounding", r.message());
        assertEquals(0, cache.groundings(), "a grounding cut short is not cached");
        SolveResult again = engine.solve(FREE3, free3(10), TIMEOUT);
        assertTrue(again.isSolved(), again.message());
    }

    @Test
    void aCountReadsAsItsOrderOfMagnitude() {
        assertEquals("8·10⁹", GroundingLimits.approx(Math.log10(8e9)));
        assertEquals("1,000", GroundingLimits.approx(3));
        assertEquals("1·10¹²", GroundingLimits.approx(Math.log10(9.99e11)));
        assertEquals("2,000 objects each", GroundingLimits.objects(new int[] {2000, 2000}));
        assertEquals("3 × 40 objects", GroundingLimits.objects(new int[] {3, 40}));
    }

    @Test
    void actionEliminationOnALongPlanReplaysEachSuffixOncePerPass() {
        // a chain of places: a shortest walk has nothing to eliminate, and checking that must not
        // replay the whole plan once per action (quadratic: 100,000 places took minutes)
        int n = 3000;
        StringBuilder init = new StringBuilder("(at o0)");
        for (int i = 0; i + 1 < n; i++) init.append(" (next o").append(i).append(" o").append(i + 1).append(')');
        Domain d = PddlParser.parseDomain("""
                (define (domain chain) (:requirements :strips :typing) (:types node)
                 (:predicates (at ?n - node) (next ?a ?b - node))
                 (:action move :parameters (?a ?b - node) :precondition (and (at ?a) (next ?a ?b)) :effect (and (at ?b) (not (at ?a)))))
                """, "chain.pddl");
        Problem p = PddlParser.parseProblem("(define (problem c) (:domain chain) (:objects " + objects(n) + " - node) (:init " + init
                + ") (:goal (at o" + (n - 1) + ")))", "chain-problem.pddl");
        GroundedProblem.Query q = new GroundedProblemCache(1).get(d, p).query(p);
        SearchTask t = q.task();
        int[] walk = UnaryGraphSearch.search(t, q.init(), q.goalPos()[0]);
        assertEquals(n - 1, walk.length);
        Successors succ = new Successors(t);
        int[] shortened = PlanShortener.shorten(t, succ, q.init(), q.goalPos(), q.goalNeg(), walk);
        assertEquals(n - 1, shortened.length);
        // linear: about two replays of the plan (cycle check, one pass), each step a one-fact state;
        // quadratic would be n²/2 = 4.5·10⁶ steps
        assertTrue(succ.work() < 20L * n, "work " + succ.work());
        assertTrue(new TriadEngine().solve(d, p, TIMEOUT).isSolved());
    }
}
