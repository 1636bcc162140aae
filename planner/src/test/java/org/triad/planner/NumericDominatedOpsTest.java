package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * A courier with a battery drained per metre who can also guide a visitor (draining and costing as much
 * as a move): guiding is left out of the search when nothing needs the visitor anywhere, kept when the
 * goal does; either way the plan is the cheapest (checked by {@link PlanValidator}).
 */
class NumericDominatedOpsTest {
    private static final String DOMAIN = """
            (define (domain courier)
              (:requirements :strips :typing :fluents :negative-preconditions)
              (:types place item person)
              (:predicates (at ?p - place) (adj ?a ?b - place) (item-at ?i - item ?p - place) (holds ?i - item) (empty)
                (person-at ?v - person ?p - place) (following ?v - person))
              (:functions (battery) (drain) (dist ?a ?b - place) (total-cost))
              (:action move :parameters (?a ?b - place)
                :precondition (and (at ?a) (adj ?a ?b) (>= (battery) (* (dist ?a ?b) (drain))))
                :effect (and (not (at ?a)) (at ?b) (decrease (battery) (* (dist ?a ?b) (drain))) (increase (total-cost) (dist ?a ?b))))
              (:action guide :parameters (?v - person ?a ?b - place)
                :precondition (and (at ?a) (person-at ?v ?a) (adj ?a ?b) (not (following ?v)) (>= (battery) (* (dist ?a ?b) (drain))))
                :effect (and (not (at ?a)) (at ?b) (not (person-at ?v ?a)) (person-at ?v ?b)
                  (decrease (battery) (* (dist ?a ?b) (drain))) (increase (total-cost) (dist ?a ?b))))
              (:action start :parameters (?v - person ?p - place) :precondition (and (at ?p) (person-at ?v ?p)) :effect (following ?v))
              (:action pick :parameters (?i - item ?p - place) :precondition (and (at ?p) (item-at ?i ?p) (empty))
                :effect (and (holds ?i) (not (empty)) (not (item-at ?i ?p))))
              (:action drop :parameters (?i - item ?p - place) :precondition (and (at ?p) (holds ?i))
                :effect (and (item-at ?i ?p) (not (holds ?i)) (empty))))""";

    private static Problem problem(String goal) {
        return PddlParser.parseProblem("""
                (define (problem errand) (:domain courier)
                  (:objects lobby store c1 ward - place gauze - item alice - person)
                  (:init (at lobby) (empty) (item-at gauze store) (person-at alice lobby)
                    (adj lobby store) (adj store lobby) (adj store c1) (adj c1 store) (adj c1 ward) (adj ward c1) (adj lobby c1) (adj c1 lobby)
                    (= (dist lobby store) 5) (= (dist store lobby) 5) (= (dist store c1) 3) (= (dist c1 store) 3)
                    (= (dist c1 ward) 4) (= (dist ward c1) 4) (= (dist lobby c1) 7) (= (dist c1 lobby) 7)
                    (= (battery) 30) (= (drain) 0.5) (= (total-cost) 0))
                  (:goal %s) (:metric minimize (total-cost)))""".formatted(goal), "errand.pddl");
    }

    private static List<String> leftOut(Domain d, Problem p) {
        NumericTask task = new NumericTask(d, p);
        boolean[] out = NumericDominatedOps.of(task);
        List<String> names = new ArrayList<>();
        if (out != null) for (int o = 0; o < out.length; o++) if (out[o]) names.add(task.ops.get(o).label());
        return names;
    }

    @Test
    void guidingIsLeftOutWhenNothingNeedsTheVisitor() {
        Domain d = PddlParser.parseDomain(DOMAIN, "courier.pddl");
        Problem p = problem("(and (item-at gauze ward) (empty))");
        List<String> out = leftOut(d, p);
        assertTrue(out.contains("(guide alice lobby store)") && out.contains("(start alice lobby)"), out.toString());
        assertTrue(out.stream().noneMatch(o -> o.startsWith("(move") || o.startsWith("(pick") || o.startsWith("(drop")), out.toString());
        SolveResult r = new TriadEngine().solve(d, p, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.toString());
        // lobby -> store (5), pick, store -> c1 -> ward (7), drop
        assertEquals(12, PlanValidator.metricValue(d, p, r.plan()).getAsDouble(), 1e-9);
        assertEquals(5, r.plan().length(), r.plan().toPddl());
    }

    @Test
    void guidingIsKeptWhenTheGoalNeedsTheVisitor() {
        Domain d = PddlParser.parseDomain(DOMAIN, "courier.pddl");
        Problem p = problem("(and (person-at alice ward) (item-at gauze ward))");
        assertTrue(leftOut(d, p).stream().noneMatch(o -> o.startsWith("(guide")), leftOut(d, p).toString());
        SolveResult r = new TriadEngine().solve(d, p, Duration.ofSeconds(60));
        assertTrue(r.isSolved(), r.toString());
        // alice guided along the courier's way: lobby -> store (5), pick, store -> c1 -> ward (7), drop
        assertEquals(12, PlanValidator.metricValue(d, p, r.plan()).getAsDouble(), 1e-9, r.plan().toPddl());
    }
}
