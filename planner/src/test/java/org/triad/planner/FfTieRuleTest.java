package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.Set;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/** Which of two equally near achievers supports a fact in the level FF heuristic. */
class FfTieRuleTest {
    /**
     * A gate reached from either of two true facts by an action of its own, then the goal: the tie is
     * at the gate (both facts can change, so the grounding keeps them as preconditions), below the
     * goal's level, where the exploration meets both achievers before it stops.
     */
    private static final Domain ROUTES = PddlParser.parseDomain("""
            (define (domain routes) (:requirements :strips)
              (:predicates (left) (right) (gate) (there))
              (:action go-left :parameters () :precondition (left) :effect (gate))
              (:action go-right :parameters () :precondition (right) :effect (gate))
              (:action through :parameters () :precondition (gate) :effect (there))
              (:action swap :parameters () :precondition (left) :effect (and (not (left)) (right))))
            """, "routes.pddl");

    @Test
    void theLastAchieverAtALevelTakesTheOtherRouteThanTheFirst() {
        Problem p = PddlParser.parseProblem("""
                (define (problem one) (:domain routes) (:init (left) (right)) (:goal (there)))
                """, "one.pddl");
        GroundedProblem.Query q = new GroundedProblem(ROUTES, p).query(p);
        FfHeuristic first = new FfHeuristic(q.task());
        FfHeuristic last = new FfHeuristic(q.task(), true);
        assertEquals(2, first.evaluate(q.init(), q.goalPos()));
        assertEquals(2, last.evaluate(q.init(), q.goalPos()));
        assertEquals(1, first.helpfulCount());
        assertEquals(1, last.helpfulCount());
        String a = q.task().ops[first.helpful(0)].name();
        String b = q.task().ops[last.helpful(0)].name();
        assertEquals(Set.of("go-left", "go-right"), Set.of(a, b));
        assertNotEquals(a, b);
    }
}
