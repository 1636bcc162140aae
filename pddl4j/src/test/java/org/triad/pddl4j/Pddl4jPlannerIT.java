package org.triad.pddl4j;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;
import org.triad.planner.SolveResult;
import org.triad.planner.PlanValidator;
import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;

class Pddl4jPlannerIT {
    static final String DOMAIN = """
            (define (domain hospital) (:requirements :strips :typing)
              (:types waypoint item - object room - waypoint)
              (:predicates (robot-at ?w - waypoint) (adj ?a ?b - waypoint) (item-at ?i - item ?w - waypoint) (holding ?i - item) (hand-empty))
              (:action move :parameters (?src ?dst - waypoint) :precondition (and (robot-at ?src) (adj ?src ?dst))
                :effect (and (robot-at ?dst) (not (robot-at ?src))))
              (:action load :parameters (?i - item ?w - waypoint) :precondition (and (robot-at ?w) (item-at ?i ?w) (hand-empty))
                :effect (and (holding ?i) (not (item-at ?i ?w)) (not (hand-empty))))
              (:action unload :parameters (?i - item ?w - waypoint) :precondition (and (robot-at ?w) (holding ?i))
                :effect (and (item-at ?i ?w) (hand-empty) (not (holding ?i)))))
            """;
    static final String PROBLEM = """
            (define (problem p) (:domain hospital) (:objects a b c - waypoint r - room i - item)
              (:init (robot-at a) (hand-empty) (item-at i b) (adj a b) (adj b a) (adj b c) (adj c b) (adj c r) (adj r c))
              (:goal (item-at i r)))
            """;

    @Test
    void ffAndHspPlansValidateAndMapBackToGroundActions() {
        Domain d = PddlParser.parseDomain(DOMAIN, "d");
        Problem p = PddlParser.parseProblem(PROBLEM, "p");
        for (Pddl4jPlanner.Search s : Pddl4jPlanner.Search.values()) {
            SolveResult r = new Pddl4jPlanner(s).solve(d, p, Duration.ofSeconds(10));
            assertEquals(SolveResult.Status.SOLVED, r.status(), s + ": " + r.message());
            assertTrue(PlanValidator.validate(d, p, r.plan()).valid(), s + ": " + r.plan().toPddl());
            assertEquals("(load i b)", r.plan().steps().get(1).toString());
        }
    }

    @Test
    void movesCostingTheirLengthArePlannedWithoutTheCostsAndOtherNumbersAreAnError() {
        String costed = """
                (define (domain costed) (:requirements :strips :typing :fluents)
                  (:types waypoint)
                  (:predicates (robot-at ?w - waypoint) (adj ?a ?b - waypoint))
                  (:functions (distance ?a ?b - waypoint) (total-cost) (battery))
                  (:action move :parameters (?src ?dst - waypoint) :precondition (and (robot-at ?src) (adj ?src ?dst))
                    :effect (and (robot-at ?dst) (not (robot-at ?src)) (increase (total-cost) (distance ?src ?dst)))))
                """;
        Problem p = PddlParser.parseProblem("""
                (define (problem p) (:domain costed) (:objects a b c - waypoint)
                  (:init (robot-at a) (adj a b) (adj b c) (= (distance a b) 4) (= (distance b c) 8) (= (total-cost) 0) (= (battery) 5))
                  (:goal (robot-at c)) (:metric minimize (total-cost)))
                """, "p");
        Domain d = PddlParser.parseDomain(costed, "d");
        SolveResult r = new Pddl4jPlanner().solve(d, p, Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.SOLVED, r.status(), r.message());
        assertTrue(PlanValidator.validate(d, p, r.plan()).valid(), r.plan().toPddl());
        assertEquals(2, r.plan().steps().size());
        // a battery the moves need is a number PDDL4J cannot plan with: handed over whole, and refused
        Domain battery = PddlParser.parseDomain(costed.replace("(adj ?src ?dst))", "(adj ?src ?dst) (>= (battery) 1))"), "d");
        assertEquals(SolveResult.Status.ERROR, new Pddl4jPlanner().solve(battery, p, Duration.ofSeconds(10)).status());
    }

    @Test
    void unreachableGoalIsNoPlanAndUnsupportedInputIsAnError() {
        Domain d = PddlParser.parseDomain(DOMAIN, "d");
        Problem island = PddlParser.parseProblem(PROBLEM.replace("(adj c r) (adj r c)", ""), "p");
        SolveResult r = new Pddl4jPlanner().solve(d, island, Duration.ofSeconds(5));
        // PDDL4J 3.8.3 answers this one with a plan that does not reach the goal; the adapter's
        // validation turns that into an error instead of passing it on
        assertTrue(r.status() == SolveResult.Status.UNSOLVABLE
                || (r.status() == SolveResult.Status.ERROR && r.message().contains("does not validate")), r.status() + " " + r.message());
        Problem unknown = PddlParser.parseProblem(PROBLEM.replace("(item-at i r)", "(item-at i nowhere)"), "p");
        assertEquals(SolveResult.Status.ERROR, new Pddl4jPlanner().solve(d, unknown, Duration.ofSeconds(5)).status());
    }

    @Test
    void theRegistryFindsThePlannerByNameAndItPrintsNoLoggingNoise() {
        ByteArrayOutputStream console = new ByteArrayOutputStream();
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        PrintStream capture = new PrintStream(console, true, StandardCharsets.UTF_8);
        SolveResult r;
        try {
            System.setOut(capture);
            System.setErr(capture);
            PddlPlanner planner = PddlPlanners.byName("pddl4j");
            assertEquals("pddl4j", planner.name());
            r = planner.solve(PddlParser.parseDomain(DOMAIN, "d"), PddlParser.parseProblem(PROBLEM, "p"), Duration.ofSeconds(10));
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        assertEquals(SolveResult.Status.SOLVED, r.status(), r.message());
        assertTrue(r.plan().toPddl().endsWith("; cost = 5 (unit cost)\n"), r.plan().toPddl());
        String noise = console.toString(StandardCharsets.UTF_8);
        assertFalse(noise.contains("ERROR") || noise.contains("Instrumentation"), noise);
    }
}
