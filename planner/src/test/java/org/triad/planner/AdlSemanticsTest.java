package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * PDDL's ADL semantics in the engine and in {@link PlanValidator}: conditional effects evaluated in
 * the state before the action, deletes before adds, quantifiers over typed objects, existential
 * preconditions, disjunctive goals, and unsolvable ADL problems.
 */
class AdlSemanticsTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(20);

    private static Domain domain(String text) {
        return PddlParser.parseDomain(text, "adl-domain.pddl");
    }

    private static Problem problem(String text) {
        return PddlParser.parseProblem(text, "adl-problem.pddl");
    }

    private static PddlPlan plan(String... steps) {
        List<PddlStep> out = new java.util.ArrayList<>();
        for (String s : steps) {
            String[] w = s.split(" ");
            out.add(new PddlStep(w[0], List.of(w).subList(1, w.length)));
        }
        return new PddlPlan(out);
    }

    /** {@code press} arms the switch and, if it was armed before, rings the bell. */
    private static final Domain BELL = domain("""
            (define (domain bell) (:requirements :adl)
              (:predicates (armed) (rung))
              (:action press :parameters ()
                :effect (and (armed) (when (armed) (rung)))))""");

    @Test
    void conditionalEffectIsEvaluatedInTheStateBeforeTheAction() {
        Problem p = problem("(define (problem b) (:domain bell) (:init) (:goal (rung)))");
        SolveResult r = TriadEngineTest.solveAndValidate(BELL, p);
        assertEquals(2, r.plan().length(), "the first press only arms: its condition is false before it");
        PlanValidator.Report once = PlanValidator.validate(BELL, p, plan("press"));
        assertFalse(once.valid());
        assertEquals("goal not satisfied at the end: (rung) is false", once.message());
        assertTrue(PlanValidator.validate(BELL, p, plan("press", "press")).valid());
    }

    @Test
    void conditionalDeleteAndUnconditionalAddOfOneFactLeaveItTrue() {
        Domain d = domain("""
                (define (domain keep) (:requirements :adl)
                  (:predicates (lamp) (done))
                  (:action touch :parameters ()
                    :effect (and (lamp) (done) (when (lamp) (not (lamp))))))""");
        Problem p = problem("(define (problem k) (:domain keep) (:init (lamp)) (:goal (and (done) (lamp))))");
        SolveResult r = TriadEngineTest.solveAndValidate(d, p);
        assertEquals(1, r.plan().length());
    }

    /** Every box (a subtype of item) that is open gets closed; crates are items too, balls are not. */
    private static final Domain CLOSER = domain("""
            (define (domain closer) (:requirements :adl :typing)
              (:types box crate - item ball)
              (:predicates (open ?i - item) (closed ?i - item) (bounced ?b - ball) (ready))
              (:action close-all :parameters ()
                :precondition (ready)
                :effect (forall (?i - box) (when (open ?i) (and (closed ?i) (not (open ?i))))))
              (:action get-ready :parameters () :effect (ready)))""");

    @Test
    void forallEffectRangesOverTheObjectsOfItsType() {
        Problem p = problem("""
                (define (problem c) (:domain closer)
                  (:objects b1 b2 - box c1 - crate)
                  (:init (open b1) (open c1))
                  (:goal (forall (?i - box) (not (open ?i)))))""");
        SolveResult r = TriadEngineTest.solveAndValidate(CLOSER, p);
        assertEquals(List.of("get-ready", "close-all"), r.plan().steps().stream().map(PddlStep::name).toList());
        Problem crate = problem("""
                (define (problem c) (:domain closer)
                  (:objects b1 - box c1 - crate)
                  (:init (open b1) (open c1))
                  (:goal (closed c1)))""");
        SolveResult none = new TriadEngine().solve(CLOSER, crate, TIMEOUT);
        assertEquals(SolveResult.Status.UNSOLVABLE, none.status(), "a crate is no box: " + none.message());
        assertFalse(PlanValidator.validate(CLOSER, crate, plan("get-ready", "close-all")).valid());
    }

    @Test
    void existentialPreconditionNeedsAWitness() {
        Domain d = domain("""
                (define (domain door) (:requirements :adl :typing)
                  (:types key person)
                  (:predicates (has ?p - person ?k - key) (fits ?k - key) (open))
                  (:action unlock :parameters (?p - person)
                    :precondition (exists (?k - key) (and (has ?p ?k) (fits ?k)))
                    :effect (open))
                  (:action take :parameters (?p - person ?k - key) :effect (has ?p ?k)))""");
        Problem p = problem("""
                (define (problem o) (:domain door)
                  (:objects ann - person k1 k2 - key)
                  (:init (fits k2) (has ann k1))
                  (:goal (open)))""");
        SolveResult r = TriadEngineTest.solveAndValidate(d, p);
        assertEquals("(take ann k2)\n(unlock ann)", r.plan().steps().stream().map(PddlStep::toString).reduce((a, b) -> a + "\n" + b).orElse(""));
        PlanValidator.Report bad = PlanValidator.validate(d, p, plan("unlock ann"));
        assertEquals("step 1 (unlock ann): precondition not satisfied: no witness for (exists (?k - key) (and (has ?p ?k) (fits ?k)))",
                bad.message());
    }

    /** A corridor a - b - c - d: the goal "at a or at d" from b is one step, "at d" alone two. */
    private static final Domain CORRIDOR = domain("""
            (define (domain corridor) (:requirements :adl :typing)
              (:types place)
              (:predicates (at ?p - place) (link ?p ?q - place) (blocked ?p - place))
              (:action go :parameters (?p ?q - place)
                :precondition (and (at ?p) (or (link ?p ?q) (link ?q ?p)) (not (blocked ?q)))
                :effect (and (at ?q) (not (at ?p)))))""");

    @Test
    void disjunctiveGoalIsReachedByItsNearestDisjunct() {
        Problem p = problem("""
                (define (problem g) (:domain corridor)
                  (:objects a b c d - place)
                  (:init (at c) (link a b) (link b c) (link c d))
                  (:goal (or (at a) (at d))))""");
        SolveResult r = TriadEngineTest.solveAndValidate(CORRIDOR, p);
        assertEquals("go c d", r.plan().steps().get(0).name() + " " + String.join(" ", r.plan().steps().get(0).args()));
        assertEquals(1, r.plan().length(), "the artificial goal operator is not part of the plan");
    }

    @Test
    void disjunctiveGoalWithImplicationAndExists() {
        Problem p = problem("""
                (define (problem g) (:domain corridor)
                  (:objects a b c d - place)
                  (:init (at a) (link a b) (link b c) (link c d) (blocked b))
                  (:goal (imply (exists (?x - place) (blocked ?x)) (at d))))""");
        SolveResult r = new TriadEngine().solve(CORRIDOR, p, TIMEOUT);
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status(), "b is blocked, so d is out of reach: " + r.message());
        Problem free = problem("""
                (define (problem g) (:domain corridor)
                  (:objects a b c d - place)
                  (:init (at a) (link a b) (link b c) (link c d))
                  (:goal (imply (exists (?x - place) (blocked ?x)) (at d))))""");
        assertEquals(0, TriadEngineTest.solveAndValidate(CORRIDOR, free).plan().length(), "nothing is blocked: the goal holds");
    }

    @Test
    void unsolvableAdlProblemGivesNoPlan() {
        // the only way to ring needs an armed switch, and the switch can only be armed while ringing
        Domain d = domain("""
                (define (domain stuck) (:requirements :adl)
                  (:predicates (armed) (rung))
                  (:action press :parameters ()
                    :precondition (or (rung) (armed))
                    :effect (and (armed) (when (armed) (rung)))))""");
        Problem p = problem("(define (problem s) (:domain stuck) (:init) (:goal (rung)))");
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status(), r.message());
        assertEquals(null, r.plan());
    }

    @Test
    void specialStripsSearchesDoNotApplyToConditionalEffects() {
        Problem p = problem("(define (problem b) (:domain bell) (:init) (:goal (rung)))");
        GroundedProblem.Query q = new GroundedProblem(BELL, p).query(p);
        assertTrue(q.task().hasConditionalEffects);
        assertFalse(UnaryGraphSearch.applies(q.task(), q.goalPos(), q.goalNeg()));
        assertFalse(CompressedGraphSearch.applies(q.task(), q.init(), q.goalPos(), q.goalNeg()));
    }

    @Test
    void conditionsDecidedByStaticFactsMakeStripsOperators() {
        Domain d = domain("""
                (define (domain lights) (:requirements :adl :typing)
                  (:types room)
                  (:predicates (wired ?r - room) (lit ?r - room) (switched))
                  (:action switch :parameters ()
                    :effect (and (switched) (forall (?r - room) (when (wired ?r) (lit ?r))))))""");
        Problem p = problem("""
                (define (problem l) (:domain lights)
                  (:objects r1 r2 - room)
                  (:init (wired r1))
                  (:goal (lit r1)))""");
        GroundedProblem.Query q = new GroundedProblem(d, p).query(p);
        assertFalse(q.task().hasConditionalEffects, "wired is static: the effect on r1 is unconditional, on r2 absent");
        assertEquals(1, TriadEngineTest.solveAndValidate(d, p).plan().length());
    }

    @Test
    void relaxedPlanPaysForMakingAFactFalseAndCountsAnOperatorOnce() {
        Domain d = domain("""
                (define (domain door) (:requirements :adl)
                  (:predicates (open) (locked) (a) (b) (c))
                  (:action close :parameters () :precondition (open) :effect (not (open)))
                  (:action lock :parameters () :precondition (not (open)) :effect (locked))
                  (:action both :parameters () :effect (and (c) (when (c) (a)) (when (c) (b)))))""");
        Problem p = problem("(define (problem q) (:domain door) (:init (open) (c)) (:goal (and (locked) (a) (b))))");
        GroundedProblem.Query q = new GroundedProblem(d, p).query(p);
        FfHeuristic h = new FfHeuristic(q.task());
        // close, lock, and one application of both (for a and b)
        assertEquals(3, h.evaluate(q.init(), q.goalPos()));
        assertEquals(3, TriadEngineTest.solveAndValidate(d, p).plan().length());
    }

    /** A line of rooms a - b - c: a room is lit if its lamp is on or a lit neighbour's door is open (recursive). */
    private static final Domain LIGHT = domain("""
            (define (domain light) (:requirements :adl :derived-predicates :typing)
              (:types room)
              (:predicates (lamp ?r - room) (door ?r ?s - room) (next ?r ?s - room) (lit ?r - room) (dark ?r - room) (done))
              (:derived (lit ?r - room) (or (lamp ?r) (exists (?s - room) (and (lit ?s) (door ?s ?r)))))
              (:derived (dark ?r - room) (not (lit ?r)))
              (:action switch-on :parameters (?r - room) :effect (lamp ?r))
              (:action open :parameters (?r ?s - room) :precondition (or (next ?r ?s) (next ?s ?r)) :effect (door ?r ?s))
              (:action finish :parameters () :precondition (forall (?r - room) (not (dark ?r))) :effect (done)))""");

    @Test
    void derivedPredicatesAreRecomputedAfterEveryActionRecursivelyAndWithNegation() {
        Problem p = problem("""
                (define (problem l) (:domain light)
                  (:objects a b c - room)
                  (:init (next a b) (next b c) (lamp a))
                  (:goal (and (lit c) (done))))""");
        SolveResult r = TriadEngineTest.solveAndValidate(LIGHT, p);
        // two doors or one lamp for c, plus one for b unless c's light spreads back: 3 or 4 steps with finish
        assertTrue(r.plan().length() <= 4, r.plan().toPddl());
        assertFalse(PlanValidator.validate(LIGHT, p, plan("finish")).valid(), "b and c are dark at first");
        assertTrue(PlanValidator.validate(LIGHT, p, plan("open a b", "open b c", "finish")).valid(),
                "light spreads through open doors: nothing is dark any more");
        PlanValidator.Report bad = PlanValidator.validate(LIGHT, p, plan("open a b", "finish"));
        assertEquals("step 2 (finish): precondition not satisfied: (dark c) is true", bad.message());
    }

    @Test
    void derivedGoalThatNeverHoldsIsUnsolvable() {
        // nothing switches a lamp off, so a stays lit: (dark a) never holds; the relaxation cannot see
        // that (it drops conditions that a derived fact be false), the exhausted search proves it
        Problem p = problem("""
                (define (problem l) (:domain light)
                  (:objects a b c - room)
                  (:init (next a b) (next b c) (lamp a))
                  (:goal (dark a)))""");
        SolveResult r = new TriadEngine().solve(LIGHT, p, TIMEOUT);
        assertEquals(SolveResult.Status.UNSOLVABLE, r.status(), r.message());
    }

    @Test
    void rulesWithNegationThroughRecursionAreAnInputError() {
        Domain d = domain("""
                (define (domain loop) (:requirements :derived-predicates)
                  (:predicates (p) (q) (r))
                  (:derived (p) (not (q)))
                  (:derived (q) (p))
                  (:action a :parameters () :effect (r)))""");
        Problem p = problem("(define (problem l) (:domain loop) (:init) (:goal (r)))");
        SolveResult r = new TriadEngine().solve(d, p, TIMEOUT);
        assertEquals(SolveResult.Status.ERROR, r.status());
        assertTrue(r.message().endsWith("depends on its own negation: the rules are not stratified"), r.message());
        assertFalse(PlanValidator.validate(d, p, plan("a")).valid());
    }
}
