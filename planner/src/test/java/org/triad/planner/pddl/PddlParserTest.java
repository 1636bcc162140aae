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
    void rejectsConditionalEffectsClearly() {
        PddlParseException e = domainError("""
                (define (domain x) (:predicates (p) (q))
                  (:action a :parameters () :precondition ()
                    :effect (when (p) (q))))""");
        assertEquals(3, e.line());
        assertEquals(13, e.column());
        assertTrue(e.detail().contains("conditional effects ('when') are not supported"));
    }

    @Test
    void rejectsAProblemGivenAsDomainAndEmptyInput() {
        assertTrue(domainError("(define (problem p) (:domain x))").detail().contains("expected '(domain NAME)'"));
        assertTrue(domainError("  ; only a comment\n").detail().contains("empty input"));
        PddlParseException e = assertThrows(PddlParseException.class,
                () -> PddlParser.parseProblem("(define (problem p) (:domain d) (:init (at ?x)) (:goal (at a)))", "p.pddl"));
        assertTrue(e.detail().contains("variable '?x' in the initial state"));
    }
}
