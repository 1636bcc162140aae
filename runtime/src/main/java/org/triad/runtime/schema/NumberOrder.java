package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.PredicateDecl;
import org.triad.planner.pddl.TypedName;

/**
 * Ordering comparisons ({@code <}, {@code <=}, {@code >}, {@code >=}) of an action's precondition in
 * STRIPS: a property's value is one of the finitely many numbers the translation names (values of the
 * state, literals of the models, goal arguments), so the order between them is a static relation,
 * written once into the problem as facts {@code (triad-less a b)} and {@code (triad-at-most a b)}.
 * NaN is less than nothing and at most nothing, as in Java.
 */
final class NumberOrder {
	static final String LESS = "triad-less";
	static final String AT_MOST = "triad-at-most";

	private boolean used;

	/** The atom saying {@code left op right}, for terms (variables or objects) naming numbers. */
	Formula.Atom atom(Expr.Op op, String left, String right) {
		used = true;
		return switch (op) {
			case LT -> Formula.Atom.of(LESS, left, right);
			case LE -> Formula.Atom.of(AT_MOST, left, right);
			case GT -> Formula.Atom.of(LESS, right, left);
			case GE -> Formula.Atom.of(AT_MOST, right, left);
			default -> throw new IllegalArgumentException(op.symbol + " is not an ordering");
		};
	}

	boolean used() {
		return used;
	}

	List<PredicateDecl> predicates() {
		List<TypedName> params = List.of(TypedName.of("?a", "object"), TypedName.of("?b", "object"));
		return List.of(new PredicateDecl(LESS, params), new PredicateDecl(AT_MOST, params));
	}

	/** The order facts between every pair of numbers the translation names. */
	List<Formula.Atom> facts(PddlNames names) {
		List<Map.Entry<String, Double>> numbers = new ArrayList<>();
		for (String name : names.objectsWithTypes().keySet()) {
			if (names.valueOf(name) instanceof Number n) {
				numbers.add(Map.entry(name, n.doubleValue()));
			}
		}
		List<Formula.Atom> facts = new ArrayList<>();
		for (Map.Entry<String, Double> a : numbers) {
			for (Map.Entry<String, Double> b : numbers) {
				if (a.getValue() < b.getValue()) {
					facts.add(Formula.Atom.of(LESS, a.getKey(), b.getKey()));
				}
				if (a.getValue() <= b.getValue()) {
					facts.add(Formula.Atom.of(AT_MOST, a.getKey(), b.getKey()));
				}
			}
		}
		return facts;
	}

	/** Whether {@code left op right} holds for two numbers (Java's semantics, NaN compares false). */
	static boolean holds(Expr.Op op, double left, double right) {
		return switch (op) {
			case LT -> left < right;
			case LE -> left <= right;
			case GT -> left > right;
			case GE -> left >= right;
			default -> throw new IllegalArgumentException(op.symbol + " is not an ordering");
		};
	}
}
