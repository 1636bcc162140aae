package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Successive goals of a courier with a battery: one grounding serves every goal, start and charge
 * level; a new distance (a value no action changes) or a charge without a value grounds again. Each
 * answer is the one a fresh grounding gives.
 */
class NumericGroundingCacheTest {
    private static final Domain DOMAIN = PddlParser.parseDomain("""
            (define (domain courier)
              (:requirements :strips :typing :fluents)
              (:types place)
              (:predicates (at ?p - place) (adj ?a ?b - place) (dock ?p - place) (visited ?p - place))
              (:functions (battery) (dist ?a ?b - place) (total-cost))
              (:action move :parameters (?a ?b - place)
                :precondition (and (at ?a) (adj ?a ?b) (>= (battery) (dist ?a ?b)))
                :effect (and (not (at ?a)) (at ?b) (visited ?b) (decrease (battery) (dist ?a ?b)) (increase (total-cost) (dist ?a ?b))))
              (:action charge :parameters (?p - place) :precondition (and (at ?p) (dock ?p) (< (battery) 100))
                :effect (and (assign (battery) 100) (increase (total-cost) 1))))""", "courier.pddl");

    private static Problem problem(String at, String goal, String battery, int farDistance) {
        return PddlParser.parseProblem("""
                (define (problem p) (:domain courier)
                  (:objects a b c d - place)
                  (:init (at %s) (dock b) (adj a b) (adj b a) (adj b c) (adj c b) (adj c d) (adj d c) (adj a d) (adj d a)
                    (= (dist a b) 20) (= (dist b a) 20) (= (dist b c) 20) (= (dist c b) 20) (= (dist c d) 20) (= (dist d c) 20)
                    (= (dist a d) %d) (= (dist d a) %d) %s (= (total-cost) 0))
                  (:goal %s) (:metric minimize (total-cost)))""".formatted(at, farDistance, farDistance, battery, goal), "p.pddl");
    }

    private static String answer(SolveResult r) {
        return r.status() + " " + (r.isSolved() ? r.plan().steps().toString() : r.message());
    }

    @Test
    void goalsAndChargeLevelsShareOneGroundingAndGetTheFreshAnswer() {
        NumericGroundingCache cache = new NumericGroundingCache(4);
        Problem[] problems = {
            problem("a", "(at d)", "(= (battery) 100)", 70),
            problem("a", "(at d)", "(= (battery) 30)", 70), // too little for a->d (70) or a->b->c->d (60) unless it charges at b
            problem("c", "(and (visited a) (at c))", "(= (battery) 100)", 70),
            problem("a", "(at d)", "(= (battery) 10)", 70), // cannot leave a: no plan
        };
        for (Problem p : problems) {
            SolveResult cached = NumericSearch.solve(DOMAIN, p, Duration.ofSeconds(60), cache);
            SolveResult fresh = NumericSearch.solve(DOMAIN, p, Duration.ofSeconds(60));
            assertEquals(answer(fresh), answer(cached));
            if (cached.isSolved()) assertTrue(PlanValidator.validate(DOMAIN, p, cached.plan()).valid(), answer(cached));
        }
        assertEquals(1, cache.groundings());
        assertEquals(3, cache.hits());
        assertTrue(answer(NumericSearch.solve(DOMAIN, problems[1], Duration.ofSeconds(60), cache)).contains("charge b"));

        // another distance is another grounding (it is folded into the instances), and so is a battery without a value
        Problem shortcut = problem("a", "(at d)", "(= (battery) 30)", 25);
        assertEquals(answer(NumericSearch.solve(DOMAIN, shortcut, Duration.ofSeconds(60))),
                answer(NumericSearch.solve(DOMAIN, shortcut, Duration.ofSeconds(60), cache)));
        Problem flat = problem("a", "(at d)", "", 70);
        assertEquals(answer(NumericSearch.solve(DOMAIN, flat, Duration.ofSeconds(60))), answer(NumericSearch.solve(DOMAIN, flat, Duration.ofSeconds(60), cache)));
        assertEquals(3, cache.groundings());
    }
}
