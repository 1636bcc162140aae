package org.triad.planner.pddl;

import java.util.List;

/**
 * A numeric expression of PDDL 2.1 (level 2): a number, a fluent {@code (f args)}, or arithmetic
 * {@code (+ a b)}, {@code (- a b)}, {@code (* a b)}, {@code (/ a b)}, {@code (- a)}. Arguments of
 * fluents are object names or variables.
 */
public sealed interface NumericExpr permits NumericExpr.Number, NumericExpr.Fluent, NumericExpr.Arithmetic, NumericExpr.Negation {

    record Number(double value) implements NumericExpr { }

    record Fluent(String name, List<String> args) implements NumericExpr {
        public Fluent { args = List.copyOf(args); }
        public static Fluent of(String name, String... args) { return new Fluent(name, List.of(args)); }
    }

    /** {@code op} is one of {@code + - * /}. */
    record Arithmetic(char op, NumericExpr left, NumericExpr right) implements NumericExpr {
        public Arithmetic {
            if ("+-*/".indexOf(op) < 0) throw new IllegalArgumentException("not an arithmetic operator: " + op);
        }
    }

    record Negation(NumericExpr operand) implements NumericExpr { }
}
