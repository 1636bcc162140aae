package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.PddlParser;

/**
 * The relaxed plan of the enforced hill-climbing's fallback (IPC 2002 settlers): a cart that does not exist yet
 * (its load undefined) must still be loaded before it unloads, and loading, which moves back what unloading moves,
 * must still support that shortfall.
 */
class NumericRelaxedPlanTest {
    private static final String DOMAIN = """
            (define (domain carts)
              (:requirements :typing :fluents)
              (:types place vehicle)
              (:predicates (at ?v - vehicle ?p - place) (potential ?v - vehicle) (built ?p - place))
              (:functions (stock ?p - place) (load ?v - vehicle))
              (:action build-cart :parameters (?p - place ?v - vehicle)
               :precondition (potential ?v)
               :effect (and (not (potential ?v)) (at ?v ?p) (assign (load ?v) 0)))
              (:action take :parameters (?v - vehicle ?p - place)
               :precondition (and (at ?v ?p) (> (stock ?p) 0))
               :effect (and (decrease (stock ?p) 1) (increase (load ?v) 1)))
              (:action give :parameters (?v - vehicle ?p - place)
               :precondition (and (at ?v ?p) (> (load ?v) 0))
               :effect (and (decrease (load ?v) 1) (increase (stock ?p) 1)))
              (:action move :parameters (?v - vehicle ?from ?to - place)
               :precondition (at ?v ?from)
               :effect (and (not (at ?v ?from)) (at ?v ?to)))
              (:action build :parameters (?p - place)
               :precondition (>= (stock ?p) 1)
               :effect (and (decrease (stock ?p) 1) (built ?p))))
            """;
    private static final String PROBLEM = """
            (define (problem deliver) (:domain carts)
              (:objects a b - place c - vehicle)
              (:init (potential c) (= (stock a) 1) (= (stock b) 0))
              (:goal (built b)))
            """;

    private static int estimate(boolean undoersLast) {
        NumericTask task = new NumericTask(PddlParser.parseDomain(DOMAIN, "carts.pddl"), PddlParser.parseProblem(PROBLEM, "deliver.pddl"));
        NumericHeuristic h = new NumericHeuristic(task);
        BitSet facts = new BitSet();
        task.initFacts.forEach(facts::set);
        return new NumericRelaxedPlan(task, h, undoersLast).evaluate(facts, task.initValues);
    }

    @Test
    void anUnbuiltCartIsLoadedBeforeItUnloads() {
        // the default's three steps and a take at a with the cart there (build-cart a); without the change: 3
        assertEquals(5, estimate(true));
    }

    @Test
    void theDefaultRelaxedPlanDropsThatShortfall() {
        // build-cart at b, give, build: the give's need of a load is dropped (the estimate the numbers-only
        // hill-climbing keeps using, so pathwaysmetric's plans stay as they were)
        assertEquals(3, estimate(false));
    }
}
