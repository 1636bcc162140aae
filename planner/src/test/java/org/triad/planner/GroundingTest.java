package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

class GroundingTest {
    @Test
    void movesAreInstantiatedOnlyAlongAdjacency() {
        Domain d = TestProblems.domain("hospital/domain.pddl");
        Problem p = TestProblems.problem("hospital/p-10-a.pddl");
        Grounder g = new Grounder(d, p);
        g.extend(p.init());
        long adj = p.init().stream().filter(a -> a.predicate().equals("adj")).count();
        long moves = g.ops.stream().filter(o -> o.name().equals("move")).count();
        assertEquals(adj, moves);
        // load/unload for 3 items at each of the 10 waypoints the robot can reach
        assertEquals(30, g.ops.stream().filter(o -> o.name().equals("load")).count());
        assertEquals(30, g.ops.stream().filter(o -> o.name().equals("unload")).count());
        // static adjacency never becomes a state fact
        assertEquals(0, g.facts.stream().filter(f -> g.predNames.get(f[0]).equals("adj")).count());
    }

    @Test
    void unreachablePartsAreNotInstantiated() {
        Domain d = TestProblems.domain("hospital/domain.pddl");
        Problem p = PddlParser.parseProblem("""
                (define (problem island) (:domain hospital)
                  (:objects a b c d - waypoint i - item)
                  (:init (robot-at a) (hand-empty) (item-at i a) (adj a b) (adj b a) (adj c d) (adj d c))
                  (:goal (robot-at b)))""", "island");
        Grounder g = new Grounder(d, p);
        g.extend(p.init());
        assertEquals(2, g.ops.stream().filter(o -> o.name().equals("move")).count());
        assertEquals(2, g.ops.stream().filter(o -> o.name().equals("load")).count());
        // continuing from a state on the island instantiates its moves
        g.extend(java.util.List.of(Formula.Atom.of("robot-at", "c")));
        assertEquals(4, g.ops.stream().filter(o -> o.name().equals("move")).count());
    }

    @Test
    void typesHierarchyEqualityAndStaticNegationFilterInstances() {
        Domain d = PddlParser.parseDomain("""
                (define (domain t) (:requirements :typing :negative-preconditions :equality)
                  (:types vehicle - object car truck - vehicle)
                  (:predicates (blocked ?v - vehicle) (swapped ?a ?b - vehicle))
                  (:action swap :parameters (?a - vehicle ?b - car)
                    :precondition (and (not (= ?a ?b)) (not (blocked ?a)))
                    :effect (swapped ?a ?b)))""", "t");
        Problem p = PddlParser.parseProblem("""
                (define (problem q) (:domain t) (:objects c1 c2 - car t1 t2 - truck)
                  (:init (blocked t2)) (:goal (swapped t1 c1)))""", "q");
        Grounder g = new Grounder(d, p);
        g.extend(p.init());
        // ?a in {c1, c2, t1} (t2 blocked), ?b in {c1, c2}, a != b: 3*2 - 2 = 4
        assertEquals(4, g.ops.size());
    }
}
