package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.BitSet;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * A courier on a line a - b - c - d (10 m a segment) fetches a box from d and brings it to a: the
 * bound from the projection on the box's place and the courier's is both legs (20 + 30 m) and the pick
 * and drop, the plan's cost, where h_max over the facts saw only the longer leg. With a second courier
 * the projection sees one courier's place only (the other's pick and drop cost 1 each from anywhere):
 * the bound stays at most the cheapest plan's cost, h_max's here.
 */
class ProjectionBoundTest {
    private static final Domain DOMAIN = PddlParser.parseDomain("""
            (define (domain courier)
              (:requirements :strips :typing :fluents)
              (:types place robot box)
              (:predicates (at ?r - robot ?p - place) (adj ?a ?b - place) (box-at ?x - box ?p - place) (carries ?r - robot ?x - box) (empty ?r - robot)
                (dock ?p - place))
              (:functions (battery) (dist ?a ?b - place) (total-cost))
              (:action move :parameters (?r - robot ?a ?b - place)
                :precondition (and (at ?r ?a) (adj ?a ?b) (>= (battery) (dist ?a ?b)))
                :effect (and (not (at ?r ?a)) (at ?r ?b) (decrease (battery) (dist ?a ?b)) (increase (total-cost) (dist ?a ?b))))
              (:action pick :parameters (?r - robot ?x - box ?p - place)
                :precondition (and (at ?r ?p) (box-at ?x ?p) (empty ?r))
                :effect (and (carries ?r ?x) (not (box-at ?x ?p)) (not (empty ?r)) (increase (total-cost) 1)))
              (:action drop :parameters (?r - robot ?x - box ?p - place)
                :precondition (and (at ?r ?p) (carries ?r ?x))
                :effect (and (box-at ?x ?p) (not (carries ?r ?x)) (empty ?r) (increase (total-cost) 1)))
              (:action charge :parameters (?r - robot ?p - place) :precondition (and (at ?r ?p) (dock ?p))
                :effect (and (assign (battery) 100) (increase (total-cost) 1))))""", "courier.pddl");

    private static Problem problem(String robots, String at) {
        return problem(robots, at, 100);
    }

    private static Problem problem(String robots, String at, int battery) {
        return PddlParser.parseProblem("""
                (define (problem p) (:domain courier)
                  (:objects a b c d - place %s - robot parcel - box)
                  (:init %s (box-at parcel d) (dock c) (adj a b) (adj b a) (adj b c) (adj c b) (adj c d) (adj d c)
                    (= (dist a b) 10) (= (dist b a) 10) (= (dist b c) 10) (= (dist c b) 10) (= (dist c d) 10) (= (dist d c) 10)
                    (= (battery) %d) (= (total-cost) 0))
                  (:goal (box-at parcel a)) (:metric minimize (total-cost)))""".formatted(robots, at, battery), "p.pddl");
    }

    private static double initialBound(Problem p) {
        NumericTask task = new NumericTask(DOMAIN, p);
        BitSet init = new BitSet();
        task.initFacts.forEach(init::set);
        return new NumericHeuristic(task).lowerBound(init, task.initValues, false);
    }

    /**
     * With 15 % the 50 m of both legs need a recharge: the bound is the cheapest way through the dock at
     * c (10 m, the recharge, then the 42 of the delivery from c), the plan's cost; the charge is read from
     * the state, so the same places with a full battery are bounded by the legs alone.
     */
    @Test
    void aChargeTooLowForEveryWayAddsTheWayThroughADock() {
        Problem low = problem("r1", "(at r1 b) (empty r1)", 15);
        assertEquals(53, initialBound(low), 1e-9);
        SolveResult r = NumericSearch.solve(DOMAIN, low, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.message());
        assertEquals(53, PlanValidator.metricValue(DOMAIN, low, r.plan()).orElseThrow(), 1e-9);
        assertTrue(r.plan().toPddl().contains("(charge r1 c)"), r.plan().toPddl());
    }

    /**
     * 60 m between neighbours, a dock at each place, 100 of charge: fetching the box from d and bringing
     * it to a needs a recharge before every leg but the first, five in all. With the charge as a
     * dimension of the projection the bound counts all five (360 m, pick, drop, 5 recharges: 367, the
     * plan's cost); reading only whether one is needed, it was 363.
     */
    @Test
    void everyRechargeATripNeedsIsCounted() {
        Problem far = farDelivery("60");
        assertEquals(367, initialBound(far), 1e-9);
        SolveResult r = NumericSearch.solve(DOMAIN, far, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.message());
        assertEquals(367, PlanValidator.metricValue(DOMAIN, far, r.plan()).orElseThrow(), 1e-9);
    }

    /** Legs of 60.4 m: the charge is counted in 256 levels of 100/255, drains rounded down, and the bound still meets the cost. */
    @Test
    void fractionalDrainsAreCountedInLevelsAndStillBound() {
        Problem far = farDelivery("60.4");
        assertEquals(6 * 60.4 + 7, initialBound(far), 1e-6);
        SolveResult r = NumericSearch.solve(DOMAIN, far, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.message());
        assertEquals(6 * 60.4 + 7, PlanValidator.metricValue(DOMAIN, far, r.plan()).orElseThrow(), 1e-6);
    }

    private static Problem farDelivery(String leg) {
        return PddlParser.parseProblem("""
                (define (problem far) (:domain courier)
                  (:objects a b c d - place r1 - robot parcel - box)
                  (:init (at r1 a) (empty r1) (box-at parcel d) (dock a) (dock b) (dock c) (dock d)
                    (adj a b) (adj b a) (adj b c) (adj c b) (adj c d) (adj d c)
                    (= (dist a b) %1$s) (= (dist b a) %1$s) (= (dist b c) %1$s) (= (dist c b) %1$s) (= (dist c d) %1$s) (= (dist d c) %1$s)
                    (= (battery) 100) (= (total-cost) 0))
                  (:goal (box-at parcel a)) (:metric minimize (total-cost)))""".formatted(leg), "far.pddl");
    }

    @Test
    void aDeliveryIsBoundedByBothLegs() {
        Problem one = problem("r1", "(at r1 b) (empty r1)");
        assertEquals(52, initialBound(one), 1e-9);
        SolveResult r = NumericSearch.solve(DOMAIN, one, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.message());
        assertEquals(52, PlanValidator.metricValue(DOMAIN, one, r.plan()).orElseThrow(), 1e-9);
    }

    @Test
    void aSecondCourierIsNotMissedByTheBound() {
        Problem two = problem("r1 r2", "(at r1 b) (empty r1) (at r2 c) (empty r2)");
        NumericTask task = new NumericTask(DOMAIN, two);
        BitSet init = new BitSet();
        task.initFacts.forEach(init::set);
        double h = new NumericHeuristic(task).lowerBound(init, task.initValues, false);
        // r2 fetches the box (10 + 1) and brings it to a (30 + 1): the bound must not exceed that
        assertTrue(h > 0 && h <= 42, "h " + h);
        SolveResult r = NumericSearch.solve(DOMAIN, two, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.message());
        assertEquals(42, PlanValidator.metricValue(DOMAIN, two, r.plan()).orElseThrow(), 1e-9);
    }
}
