package org.triad.planner.pddl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class PddlParserTest {
    private static final String DOMAIN = """
            ; a comment before the definition
            (DEFINE (Domain Mini)   ; names are case-insensitive
              (:requirements :strips :typing :negative-preconditions :equality)
              (:types room - place door)
              (:constants home - place)
              (:predicates (at ?p - place) (open ?d - door) (link ?a ?b - (either place room) ?d - door))
              (:action Go
                :parameters (?from ?to - place ?d - door)
                :precondition (and (AT ?from) (link ?from ?to ?d) (open ?d) (not (= ?from ?to)))
                :effect (and (at ?to) (not (at ?from))))
              (:action shut :parameters (?d - door) :precondition (imply (open ?d) (forall (?p - place) (not (at ?p))))
                :effect (forall (?e - door) (not (open ?e)))))
            """;

    @Test
    void parsesTypesConstantsEitherAndFormulas() {
        Domain d = PddlParser.parseDomain(DOMAIN, "mini.pddl");
        assertEquals("mini", d.name());
        assertEquals(List.of(TypedName.of("room", "place"), TypedName.of("door", "object")), d.types());
        assertEquals(List.of(TypedName.of("home", "place")), d.constants());
        assertEquals(List.of("place", "room"), d.predicates().get(2).parameters().get(1).types());
        Action go = d.action("go");
        assertEquals(3, go.parameters().size());
        Formula.And pre = (Formula.And) go.precondition();
        assertEquals(Formula.Atom.of("at", "?from"), pre.parts().get(0));
        assertEquals(new Formula.Not(new Formula.Equals("?from", "?to")), pre.parts().get(3));
        assertEquals(List.of(new PddlEffect.Add(Formula.Atom.of("at", "?to")), new PddlEffect.Delete(Formula.Atom.of("at", "?from"))), go.effects());
        assertTrue(d.action("shut").precondition() instanceof Formula.Imply);
        assertTrue(d.action("shut").effects().get(0) instanceof PddlEffect.Forall);
    }

    @Test
    void parsesProblemWithActionCosts() {
        Problem p = PddlParser.parseProblem("""
                (define (problem p1) (:domain mini)
                  (:objects a b - place d1 - door)
                  (:init (at a) (open d1) (= (total-cost) 0) (= (dist a b) 7))
                  (:goal (and (at b)))
                  (:metric minimize (total-cost)))
                """, "p1.pddl");
        assertEquals(3, p.objects().size());
        assertEquals(List.of(Formula.Atom.of("at", "a"), Formula.Atom.of("open", "d1")), p.init());
        assertEquals(new Problem.NumericFact("dist", List.of("a", "b"), 7), p.numericInit().get(1));
        assertEquals("minimize (total-cost)", p.metric());
    }

    private static PddlParseException domainError(String text) {
        return assertThrows(PddlParseException.class, () -> PddlParser.parseDomain(text, "bad.pddl"));
    }

    @Test
    void reportsMissingParenthesisAtTheOpeningOne() {
        PddlParseException e = domainError("(define (domain x)\n  (:predicates (p)\n");
        assertEquals(2, e.line());
        assertEquals(3, e.column());
        assertTrue(e.getMessage().startsWith("bad.pddl:2:3: "), e.getMessage());
        assertTrue(e.detail().contains("missing ')'"), e.detail());
    }

    @Test
    void reportsUnexpectedClosingParenthesis() {
        PddlParseException e = domainError("(define (domain x))\n )");
        assertEquals(2, e.line());
        assertEquals(2, e.column());
    }

    @Test
    void reportsUnknownSectionWithPosition() {
        PddlParseException e = domainError("(define (domain x)\n\n    (:predicatez (p)))");
        assertEquals("bad.pddl:3:5: unknown domain section ':predicatez'", e.getMessage());
    }

    @Test
    void rejectsUndeclaredPredicatesAndUnboundVariables() {
        assertTrue(domainError("(define (domain x) (:predicates (p)) (:action a :parameters () :precondition (q) :effect (p)))")
                .detail().contains("undeclared predicate 'q'"));
        assertTrue(domainError("(define (domain x) (:predicates (p ?x)) (:action a :parameters () :precondition (p ?y) :effect ()))")
                .detail().contains("variable '?y' is not a parameter of action 'a'"));
    }

    @Test
    void readsConditionalEffectsInsideForall() {
        Domain d = PddlParser.parseDomain("""
                (define (domain x) (:requirements :adl) (:types item) (:predicates (p ?i - item) (q ?i - item) (r))
                  (:action a :parameters () :precondition ()
                    :effect (forall (?i - item) (when (and (p ?i) (not (r))) (and (q ?i) (not (p ?i)))))))""", "x.pddl");
        PddlEffect.Forall all = (PddlEffect.Forall) d.action("a").effects().get(0);
        PddlEffect.When when = (PddlEffect.When) all.body().get(0);
        assertEquals(new Formula.And(List.of(Formula.Atom.of("p", "?i"), new Formula.Not(Formula.Atom.of("r")))), when.condition());
        assertEquals(List.of(new PddlEffect.Add(Formula.Atom.of("q", "?i")), new PddlEffect.Delete(Formula.Atom.of("p", "?i"))), when.body());
    }

    @Test
    void rejectsMalformedAdlFormulasWithTheirPosition() {
        PddlParseException e = domainError("""
                (define (domain x) (:predicates (p) (q))
                  (:action a :parameters () :precondition ()
                    :effect (when (p))))""");
        assertEquals("bad.pddl:3:13: 'when' takes a condition and an effect", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q))
                  (:action a :parameters () :precondition (forall (?x) (p ?x) (q))
                    :effect (q)))""");
        assertEquals("bad.pddl:2:43: 'forall' takes a variable list and a formula", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q))
                  (:action a :parameters () :precondition (exists ?x (p ?x))
                    :effect (q)))""");
        assertEquals("bad.pddl:2:51: expected a variable list in parentheses, found '?x'", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p) (q))
                  (:action a :parameters () :precondition (imply (p))
                    :effect (q)))""");
        assertEquals("bad.pddl:2:43: 'imply' takes exactly two formulas", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p) (q))
                  (:action a :parameters () :precondition (and (q) (when (p) (q)))
                    :effect (q)))""");
        assertEquals("bad.pddl:2:52: 'when' is an effect, not a formula", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p) (q))
                  (:action a :parameters () :precondition ()
                    :effect (when (p) (or (q) (p)))))""");
        assertEquals("bad.pddl:3:23: expected an atom in an effect", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q))
                  (:action a :parameters () :precondition ()
                    :effect (when (p ?y) (q))))""");
        assertEquals("bad.pddl:2:3: variable '?y' is not a parameter of action 'a'", e.getMessage());
    }

    @Test
    void readsDerivedPredicatesAndRejectsBadRulesWithTheirPosition() {
        Domain d = PddlParser.parseDomain("""
                (define (domain x) (:requirements :derived-predicates) (:predicates (p ?x) (q ?x))
                  (:derived (q ?x) (p ?x))
                  (:action a :parameters (?x) :precondition (q ?x) :effect (not (p ?x))))""", "x.pddl");
        assertEquals(List.of(new Axiom("q", List.of(TypedName.of("?x", "object")), Formula.Atom.of("p", "?x"))), d.axioms());
        assertEquals(d, PddlParser.parseDomain(PddlWriter.write(d), "written.pddl"));
        PddlParseException e = domainError("""
                (define (domain x) (:predicates (p ?x))
                  (:derived (q ?x) (p ?x)))""");
        assertEquals("bad.pddl:2:3: derived predicate 'q' is not declared in :predicates", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q ?x))
                  (:derived (q ?x) (p ?x))
                  (:action a :parameters (?x) :effect (q ?x)))""");
        assertEquals("bad.pddl:2:3: derived predicate 'q' is changed by an action effect", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q ?x))
                  (:derived (q ?x) (p ?y)))""");
        assertEquals("bad.pddl:2:3: variable '?y' is not a parameter of derived predicate 'q'", e.getMessage());
        e = domainError("""
                (define (domain x) (:predicates (p ?x) (q ?x))
                  (:derived (q ?x)))""");
        assertEquals("bad.pddl:2:3: expected '(:derived (PREDICATE PARAMETERS) FORMULA)'", e.getMessage());
    }

    @Test
    void rejectsAProblemGivenAsDomainAndEmptyInput() {
        assertTrue(domainError("(define (problem p) (:domain x))").detail().contains("expected '(domain NAME)'"));
        assertTrue(domainError("  ; only a comment\n").detail().contains("empty input"));
        PddlParseException e = assertThrows(PddlParseException.class,
                () -> PddlParser.parseProblem("(define (problem p) (:domain d) (:init (at ?x)) (:goal (at a)))", "p.pddl"));
        assertTrue(e.detail().contains("variable '?x' in the initial state"));
    }

    @Test
    void splitsNamesFromVariablesWithoutSpaces() {
        Domain d = PddlParser.parseDomain("""
                (define (domain zeno) (:requirements :typing)
                  (:types aircraft city)
                  (:predicates (at?x - aircraft ?c - city) (AIRCRAFT?a))
                  (:action fly :parameters (?a - aircraft?from ?to - city)
                    :precondition (and (aircraft?a)(at ?a?from))
                    :effect (and (at?a ?to) (not(at ?a ?from)))))""", "zeno.pddl");
        assertEquals(List.of(TypedName.of("?x", "aircraft"), TypedName.of("?c", "city")), d.predicates().get(0).parameters());
        Action fly = d.action("fly");
        assertEquals(List.of("?a", "?from", "?to"), fly.parameters().stream().map(TypedName::name).toList());
        assertEquals(new Formula.And(List.of(Formula.Atom.of("aircraft", "?a"), Formula.Atom.of("at", "?a", "?from"))), fly.precondition());
    }

    @Test
    void readsCommentsAnywhereAndIgnoresCase() {
        Problem p = PddlParser.parseProblem("""
                (define;comment right after a keyword
                 (PROBLEM P1) (:Domain ZENO);another
                 (:objects A1;a name ends at a comment
                   - Aircraft C1 c2 - city)
                 (:INIT (AT a1 C1)) (:goal (and ; goal
                   (at A1 c2))))""", "p.pddl");
        assertEquals("p1", p.name());
        assertEquals(List.of(TypedName.of("a1", "aircraft"), TypedName.of("c1", "city"), TypedName.of("c2", "city")), p.objects());
        assertEquals(List.of(Formula.Atom.of("at", "a1", "c1")), p.init());
    }

    @Test
    void checksRequirementsAndNamesEachUnsupportedOneAtItsPlace() {
        Domain d = PddlParser.parseDomain("(define (domain x) (:requirements :STRIPS :typing :adl :action-costs) (:predicates (p)))", "ok.pddl");
        assertEquals(List.of(":strips", ":typing", ":adl", ":action-costs"), d.requirements());
        PddlParseException e = domainError("(define (domain x)\n  (:requirements :strips :durative-actions :preferences :strps)\n  (:predicates (p)))");
        assertEquals(2, e.line());
        assertEquals(26, e.column());
        assertTrue(e.detail().startsWith("unsupported requirements ':durative-actions', ':preferences' (2:44), ':strps' (2:57) (not a PDDL requirement);"),
                e.detail());
        assertTrue(e.detail().contains("supports :action-costs :adl"), e.detail());
        PddlParseException inProblem = assertThrows(PddlParseException.class, () -> PddlParser.parseProblem(
                "(define (problem p) (:domain x)\n (:requirements :timed-initial-literals) (:init) (:goal (and)))", "p.pddl"));
        assertTrue(inProblem.getMessage().startsWith("p.pddl:2:17: unsupported requirement ':timed-initial-literals';"), inProblem.getMessage());
        assertTrue(domainError("(define (domain x) (:requirements strips) (:predicates (p)))").detail()
                .contains("expected a requirement such as ':strips', found 'strips'"));
    }

    /** A goal nested {@code depth} levels deep: {@code (and (and ... (at b)))}. */
    static String deepGoalProblem(int depth) {
        return "(define (problem deep) (:domain mini) (:objects a b - place d1 - door)\n"
                + " (:init (at a) (open d1) (link a b d1))\n (:goal " + "(and ".repeat(depth) + "(at b)" + ")".repeat(depth) + "))";
    }

    @Test
    void rejectsAbsurdNestingWithALocatedErrorInsteadOfOverflowingTheStack() {
        PddlParseException e = assertThrows(PddlParseException.class, () -> PddlParser.parseProblem(deepGoalProblem(20_000), "deep.pddl"));
        assertEquals(3, e.line());
        assertEquals(9 + 5 * (SExpr.MAX_DEPTH - 2), e.column());
        assertEquals("expressions nested deeper than " + SExpr.MAX_DEPTH + " levels", e.detail());
        PddlParseException unbalanced = assertThrows(PddlParseException.class,
                () -> PddlParser.parseProblem("(define (problem p) (:domain d) (:goal " + "(".repeat(200), "u.pddl"));
        assertTrue(unbalanced.detail().contains("missing ')'"), unbalanced.detail());
    }

    @Test
    void readsTheDeepestAcceptedNesting() {
        // define, :goal, the and's and the atom: MAX_DEPTH lists in all
        Problem p = PddlParser.parseProblem(deepGoalProblem(SExpr.MAX_DEPTH - 3), "deep.pddl");
        Formula f = p.goal();
        int depth = 0;
        while (f instanceof Formula.And a) {
            f = a.parts().get(0);
            depth++;
        }
        assertEquals(SExpr.MAX_DEPTH - 3, depth);
        assertEquals(Formula.Atom.of("at", "b"), f);
    }

    @Test
    void readsWideInputWithoutDeepRecursion() {
        StringBuilder init = new StringBuilder();
        for (int i = 0; i < 50_000; i++) init.append("(link a b d").append(i).append(") ");
        Problem p = PddlParser.parseProblem("(define (problem wide) (:domain mini) (:init " + init + ") (:goal (at b)))", "wide.pddl");
        assertEquals(50_000, p.init().size());
    }
}
