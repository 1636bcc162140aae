package org.triad.runtime.schema;

import java.util.List;

/**
 * A condition or value of an application model at runtime: the expression language of actors,
 * goals and situations, without source positions. Generated code builds these trees once; the
 * runtime evaluates them against states and translates them for planners.
 */
public sealed interface Expr {
	/** {@code left && right}. */
	record And(Expr left, Expr right) implements Expr {
	}

	/** {@code left || right}. */
	record Or(Expr left, Expr right) implements Expr {
	}

	/** {@code !operand}. */
	record Not(Expr operand) implements Expr {
	}

	/** A comparison; {@code ==} and {@code !=} on any values, the others on numbers. */
	record Compare(Op op, Expr left, Expr right) implements Expr {
	}

	enum Op {
		EQ("=="), NE("!="), LT("<"), LE("<="), GT(">"), GE(">=");

		public final String symbol;

		Op(String symbol) {
			this.symbol = symbol;
		}
	}

	/** Arithmetic on numbers: {@code op} is one of {@code + - * /}; {@code /} divides as doubles do. */
	record Arith(char op, Expr left, Expr right) implements Expr {
		public Arith {
			if ("+-*/".indexOf(op) < 0) {
				throw new IllegalArgumentException("not an arithmetic operator: " + op);
			}
		}
	}

	/** A property of an actor applied to arguments. */
	record Call(String actor, String property, List<Expr> args) implements Expr {
		public Call {
			args = List.copyOf(args);
		}
	}

	/** A parameter (of an action or goal) or an object name (in situations), bound when evaluated. */
	record Var(String name) implements Expr {
	}

	/** A literal: Boolean, Integer, Double or String. */
	record Lit(Object value) implements Expr {
	}

	/** A literal of an enumeration of the class diagram. */
	record EnumLit(String enumeration, String literal) implements Expr {
	}

	static Expr and(Expr a, Expr b) {
		return new And(a, b);
	}

	static Expr eq(Expr a, Expr b) {
		return new Compare(Op.EQ, a, b);
	}

	static Expr call(String actor, String property, Expr... args) {
		return new Call(actor, property, List.of(args));
	}

	static Expr var(String name) {
		return new Var(name);
	}

	static Expr not(Expr e) {
		return new Not(e);
	}

	Expr TRUE = new Lit(Boolean.TRUE);
}
