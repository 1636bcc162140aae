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

    private static final String BATTERY = "(define (domain b) (:requirements :typing :fluents) (:types r place) (:predicates (at ?r - r ?p - place))\n"
            + " (:functions (battery ?r - r) (distance ?a ?b - place) (capacity ?r - r) (travelled))\n"
            + " (:action drive :parameters (?r - r ?a ?b - place) :precondition (and (at ?r ?a) (>= (battery ?r) (distance ?a ?b)))\n"
            + "  :effect (and (not (at ?r ?a)) (at ?r ?b) (decrease (battery ?r) (distance ?a ?b)) (increase (travelled) (distance ?a ?b)))))";

    private static Problem problem(String init, String goal, String metric) {
        return PddlParser.parseProblem("(define (problem p) (:domain b) (:objects r1 - r x y - place)\n (:init (at r1 x) " + init + ")\n (:goal "
                + goal + ")" + (metric.isEmpty() ? "" : "\n (:metric " + metric + ")") + ")", "p.pddl", PddlParser.parseDomain(BATTERY, "b.pddl"));
    }

    @Test
    void aGoalOrMetricThatReadsAFluentWithoutValueIsALocatedError() {
        // no value in :init and no action assigns one: the goal can never hold, the metric never be computed
        assertEquals("p.pddl:3:27: the goal reads (capacity r1), which :init gives no value and no action assigns, so it could never hold;"
                + " give it one with (= (capacity r1) NUMBER)", assertThrows(PddlParseException.class,
                () -> problem("(= (battery r1) 10) (= (distance x y) 4)", "(and (at r1 y) (> (capacity r1) 0))", "")).getMessage());
        assertEquals("p.pddl:4:23: the metric reads (travelled), which :init gives no value and no action assigns, so no plan has a value;"
                + " give it one with (= (travelled) NUMBER)", assertThrows(PddlParseException.class,
                () -> problem("(= (battery r1) 10) (= (distance x y) 4)", "(at r1 y)", "minimize (+ (travelled) 1)")).getMessage());
    }

    @Test
    void aFluentWithoutValueThatOnlyActionsReadIsPddlsUndefinedValueNotAnError() {
        // PDDL 2.1: the instances that read it do not apply (IPC problems leave out the roads that are not there)
        assertEquals(1, problem("(= (battery r1) 10) (= (travelled) 0)", "(at r1 y)", "minimize (travelled)").numericInit().size() - 1);
        // total-cost and total-time start at 0; a value the goal reads is given; a quantified term is the engine's to ground
        problem("(= (battery r1) 10) (= (capacity r1) 5)", "(and (> (capacity r1) 1) (forall (?p - place) (< (distance ?p ?p) 9)))", "minimize (total-cost)");
    }
}
