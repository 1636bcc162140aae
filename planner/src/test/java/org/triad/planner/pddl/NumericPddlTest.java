package org.triad.planner.pddl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** PDDL 2.1 numeric expressions, comparisons and effects as the parser reads them, and where it refuses them. */
class NumericPddlTest {
    private static final String HEAD = "(define (domain d) (:requirements :typing :fluents) (:types r) (:predicates (p ?x - r))\n"
            + " (:functions (f ?x - r) (g))\n";

    private static Action action(String pre, String eff) {
        return PddlParser.parseDomain(HEAD + " (:action a :parameters (?x - r) :precondition " + pre + " :effect " + eff + "))", "d.pddl")
                .actions().get(0);
    }

    @Test
    void readsComparisonsArithmeticAndEveryNumericEffect() {
        Action a = action("(and (p ?x) (<= (+ (f ?x) 1 2) (* 2 (g))) (= (f ?x) (- (g))) (= ?x ?x))",
                "(and (assign (f ?x) (/ (g) 4)) (increase (g) (f ?x)) (decrease (g) 1) (scale-up (f ?x) 2) (scale-down (g) 2) (increase (total-cost) 3))");
        NumericExpr fx = NumericExpr.Fluent.of("f", "?x");
        NumericExpr g = NumericExpr.Fluent.of("g");
        assertEquals(new Formula.And(List.of(Formula.Atom.of("p", "?x"),
                new Formula.Compare("<=", new NumericExpr.Arithmetic('+', new NumericExpr.Arithmetic('+', fx, new NumericExpr.Number(1)),
                        new NumericExpr.Number(2)), new NumericExpr.Arithmetic('*', new NumericExpr.Number(2), g)),
                new Formula.Compare("=", fx, new NumericExpr.Negation(g)), new Formula.Equals("?x", "?x"))), a.precondition());
        assertEquals(List.of("assign", "increase", "decrease", "scale-up", "scale-down"),
                a.effects().stream().filter(e -> e instanceof PddlEffect.NumericEffect).map(e -> ((PddlEffect.NumericEffect) e).kind()).toList());
        assertEquals(new PddlEffect.Increase("total-cost", new NumericTerm.Constant(3)), a.effects().get(5));
        assertEquals("(<= (+ (+ (f ?x) 1) 2) (* 2 (g)))", PddlWriter.formula(((Formula.And) a.precondition()).parts().get(1)));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "(< (f ?x))|'<' takes exactly two numeric expressions",
            "(< (f ?x) NaN)|'nan' is not a finite number",
            "(< (f ?x) 1e999)|'1e999' is not a finite number (too large for a double)",
            "(< (f ?x) 0x1p3)|expected a number or a function term such as (battery ?r), found '0x1p3'",
            "(< (f ?x) ?x)|'?x' is a variable, which stands for an object, not a number: numeric comparisons and effects need numbers or function terms such as (battery ?r)",
            "(< (f ?x) lobby)|'lobby' is an object, not a number: numeric comparisons and effects need numbers or function terms such as (battery ?r)",
            "(= ?x 5)|'?x' is a variable, which stands for an object, not a number: numeric comparisons and effects need numbers or function terms such as (battery ?r)",
            "(< (f ?x) (/ 1 0))|division by zero: '(/ ... 0)'",
            "(> (/ (f ?x)) 1)|'/' takes two numeric expressions",
            "(> (h ?x) 1)|action 'a' uses undeclared function 'h'",
            "(> (f ?y) 1)|variable '?y' is not a parameter of action 'a'" })
    void badNumbersAreLocated(String pre, String message) {
        PddlParseException e = assertThrows(PddlParseException.class, () -> action(pre, "(p ?x)"));
        assertEquals(message, e.detail());
        assertEquals(true, e.line() >= 1, e.getMessage());
    }

    @Test
    void aDashGluedToItsTypeNamesTheType() {
        Domain d = PddlParser.parseDomain("(define (domain d) (:types place - object depot market -place) (:predicates (p)))", "d.pddl");
        assertEquals(List.of(TypedName.of("place", "object"), TypedName.of("depot", "place"), TypedName.of("market", "place")), d.types());
    }

    @Test
    void theNumericRequirementsAreAccepted() {
        Domain d = PddlParser.parseDomain("(define (domain d) (:requirements :numeric-fluents :fluents) (:predicates (p)))", "d.pddl");
        assertEquals(List.of(":numeric-fluents", ":fluents"), d.requirements());
    }
}
