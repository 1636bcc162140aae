package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

class UnreachableGoalTest {
    private static final Domain ROOMS = PddlParser.parseDomain("""
            (define (domain rooms) (:requirements :strips :typing)
              (:types room item)
              (:predicates (at ?r - room) (door ?a ?b - room) (item-at ?i - item ?r - room) (carries ?i - item) (hand-empty))
              (:action go :parameters (?a ?b - room) :precondition (and (at ?a) (door ?a ?b)) :effect (and (at ?b) (not (at ?a))))
              (:action pick :parameters (?i - item ?r - room) :precondition (and (at ?r) (item-at ?i ?r) (hand-empty))
                :effect (and (carries ?i) (not (item-at ?i ?r)) (not (hand-empty))))
              (:action drop :parameters (?i - item ?r - room) :precondition (and (at ?r) (carries ?i))
                :effect (and (item-at ?i ?r) (not (carries ?i)) (hand-empty))))""", "rooms.pddl");

    /** a-b-c in a row, d beyond c; the door c-d and d-c are missing unless {@code open}. */
    private static Problem problem(String goal, boolean gauzeInB, boolean cdOpen) {
        return PddlParser.parseProblem("(define (problem p) (:domain rooms) (:objects a b c d - room gauze box - item)\n"
                + " (:init (at a) (hand-empty) (door a b) (door b a) (door b c) (door c b) (door d c) (item-at box a)"
                + (gauzeInB ? " (item-at gauze b)" : "") + (cdOpen ? " (door c d)" : "") + ")\n (:goal " + goal + "))", "p.pddl");
    }

    private static SolveResult solve(Problem p) {
        return new TriadEngine().solve(ROOMS, p, Duration.ofSeconds(10));
    }

    @Test
    void anItemThatIsNowhereIsTheNearestMissingFact() {
        SolveResult r = solve(problem("(carries gauze)", false, true));
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status());
        assertEquals(1, r.unreachable().size());
        UnreachableGoal u = r.unreachable().get(0);
        assertEquals(Formula.Atom.of("carries", "gauze"), u.goal());
        assertEquals(List.of(), u.needs());
        assertEquals(List.of(Formula.Atom.of("item-at", "gauze", "_")), u.missing());
        assertEquals(UnreachableGoal.Kind.UNREACHED, u.kind());
        assertEquals("goal atom is unreachable even ignoring delete effects: (carries gauze) needs (item-at gauze _): "
                + "none in the initial state, and no action makes one from reachable facts", r.message());
    }

    @Test
    void aMissingConnectionIsNamedAtTheBoundaryOfWhatCanBeReached() {
        // delivering the box to d: the box can be carried anywhere the robot goes, but d is cut off
        SolveResult r = solve(problem("(and (item-at box d) (at c))", true, false));
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status());
        UnreachableGoal u = r.unreachable().get(0);
        assertEquals(Formula.Atom.of("item-at", "box", "d"), u.goal());
        assertEquals(List.of(Formula.Atom.of("at", "d")), u.needs());
        assertEquals(List.of(Formula.Atom.of("door", "_", "d")), u.missing());
        assertEquals(UnreachableGoal.Kind.STATIC, u.kind());
        assertEquals("(item-at box d) needs (at d): the actions that could reach it need (door _ d) (for any reachable _), which the initial state lacks", u.toString());
    }

    @Test
    void everyUnreachableGoalAtomIsExplainedAndReachableOnesAreNot() {
        SolveResult r = solve(problem("(and (at d) (carries gauze) (at c))", false, false));
        assertEquals(List.of(Formula.Atom.of("at", "d"), Formula.Atom.of("carries", "gauze")),
                r.unreachable().stream().map(UnreachableGoal::goal).toList());
        assertEquals(List.of(Formula.Atom.of("door", "_", "d")), r.unreachable().get(0).missing());
        assertTrue(r.message().startsWith("goal atoms are unreachable even ignoring delete effects: (at d): the actions that could reach it need (door _ d) (for any reachable _), which the initial state lacks;"),
                r.message());
    }

    @Test
    void reachabilityIsFromTheCurrentStateEvenWhenTheGroundingWasExtendedByAnEarlierOne() {
        TriadEngine engine = new TriadEngine();
        Problem open = problem("(at d)", true, true);
        assertTrue(engine.solve(ROOMS, open, Duration.ofSeconds(10)).isSolved());
        // same statics, but now the robot starts in d's dead end without ... the gauze gone from b: a later goal
        List<Formula.Atom> init = new ArrayList<>(open.init());
        init.remove(Formula.Atom.of("item-at", "gauze", "b"));
        SolveResult r = engine.solve(ROOMS, open.with(init, Formula.Atom.of("carries", "gauze")), Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status());
        assertEquals(List.of(Formula.Atom.of("item-at", "gauze", "_")), r.unreachable().get(0).missing());
        assertEquals(1, engine.cache().groundings(), "the explanation uses the cached grounding");
    }
}
