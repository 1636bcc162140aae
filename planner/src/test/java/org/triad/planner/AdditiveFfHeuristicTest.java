package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/** FF with h^add supporters against FF with level supporters. */
class AdditiveFfHeuristicTest {
    /** The goal by one action needing four parts (each one step away), or by a chain of three steps. */
    private static final Domain PARTS = PddlParser.parseDomain("""
            (define (domain parts) (:requirements :strips)
              (:predicates (start) (part ?x) (have ?x) (quad ?a ?b ?c ?d) (mid) (near) (done) (blocked))
              (:action make :parameters (?x) :precondition (and (start) (part ?x)) :effect (have ?x))
              (:action join :parameters (?a ?b ?c ?d) :precondition (and (quad ?a ?b ?c ?d) (have ?a) (have ?b) (have ?c) (have ?d)) :effect (done))
              (:action unblock :parameters () :precondition (blocked) :effect (and (blocked) (done)))
              (:action step :parameters () :precondition (start) :effect (mid))
              (:action close-in :parameters () :precondition (mid) :effect (near))
              (:action finish :parameters () :precondition (near) :effect (done)))
            """, "parts.pddl");

    private static GroundedProblem.Query query(String goal) {
        Problem p = PddlParser.parseProblem("""
                (define (problem four) (:domain parts) (:objects p1 p2 p3 p4)
                  (:init (start) (part p1) (part p2) (part p3) (part p4) (quad p1 p2 p3 p4))
                  (:goal %s))
                """.formatted(goal), "four.pddl");
        return new GroundedProblem(PARTS, p).query(p);
    }

    @Test
    void theCheaperAchieverInSummedCostMakesTheRelaxedPlan() {
        GroundedProblem.Query q = query("(done)");
        // levels: join reaches done first (level 2) with five actions; the chain needs three
        assertEquals(5, new FfHeuristic(q.task()).evaluate(q.init(), q.goalPos()));
        AdditiveFfHeuristic h = new AdditiveFfHeuristic(q.task());
        assertEquals(3, h.evaluate(q.init(), q.goalPos()));
        assertEquals(1, h.helpfulCount());
        assertEquals("step", q.task().ops[h.helpful(0)].name());
    }

    @Test
    void goalsTrueAlreadyCostNothingAndUnreachableOnesAreInfinite() {
        GroundedProblem.Query q = query("(and (start) (have p1) (near))");
        AdditiveFfHeuristic h = new AdditiveFfHeuristic(q.task());
        assertEquals(3, h.evaluate(q.init(), q.goalPos()));
        assertEquals(0, h.evaluate(q.init(), new int[0]));
        GroundedProblem.Query never = query("(blocked)");
        assertEquals(FfHeuristic.INFINITE, new AdditiveFfHeuristic(never.task()).evaluate(never.init(), never.goalPos()));
    }

    /** A goal only a conditional effect reaches, behind a fact that must be false first. */
    private static final Domain SWITCHES = PddlParser.parseDomain("""
            (define (domain switches) (:requirements :adl)
              (:predicates (lit ?x) (armed) (locked))
              (:action arm :parameters () :precondition (not (locked)) :effect (armed))
              (:action unlock :parameters () :precondition (locked) :effect (not (locked)))
              (:action press :parameters (?x) :precondition (and)
                :effect (when (armed) (lit ?x))))
            """, "switches.pddl");

    @Test
    void conditionalEffectsAndFactsNeededFalseAreRelaxedAsFfRelaxesThem() {
        Problem p = PddlParser.parseProblem("""
                (define (problem two) (:domain switches) (:objects a b)
                  (:init (locked))
                  (:goal (and (lit a) (lit b))))
                """, "two.pddl");
        GroundedProblem.Query q = new GroundedProblem(SWITCHES, p).query(p);
        AdditiveFfHeuristic h = new AdditiveFfHeuristic(q.task());
        // unlock, arm, press a, press b: each action once, though each press is a relaxed operator of its own
        assertEquals(4, h.evaluate(q.init(), q.goalPos()));
        assertEquals(new FfHeuristic(q.task()).evaluate(q.init(), q.goalPos()), h.evaluate(q.init(), q.goalPos()));
        assertEquals(1, h.helpfulCount());
        assertEquals("unlock", q.task().ops[h.helpful(0)].name());
    }
}
