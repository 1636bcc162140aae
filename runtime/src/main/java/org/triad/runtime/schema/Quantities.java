package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Which numeric properties are <em>quantities</em>, planned as numeric fluents of PDDL 2.1 (as Metric-FF
 * plans them): the models do arithmetic with them, charge them as a cost, set them from arithmetic or
 * another property, or compare them with a quantity. Other numeric properties stay values, named objects
 * compared by a static order ({@link NumberOrder}). The checker applies the same rule to the models
 * ({@code org.triad.dsl.semantics.Quantities}), so whatever it accepts translates.
 */
final class Quantities {
	private final AppSchema schema;
	private final Set<String> quantities = new LinkedHashSet<>();

	Quantities(AppSchema schema) {
		this.schema = schema;
		List<Expr> all = new ArrayList<>();
		List<Expr.Compare> comparisons = new ArrayList<>();
		for (ActionSchema a : schema.actions()) {
			all.add(a.pre());
			if (a.cost() != null) {
				addCalls(leaves(a.cost()));
				all.add(a.cost());
			}
			for (Effect e : a.effects()) {
				if (e.isAssignment() && (e.value() instanceof Expr.Arith || e.value() instanceof Expr.Call c && isNumeric(c))) {
					quantities.add(key(e.call()));
					addCalls(leaves(e.value()));
				}
				if (e.isAssignment()) {
					all.add(e.value());
					comparisons.add(new Expr.Compare(Expr.Op.EQ, e.call(), e.value()));
				}
			}
		}
		for (GoalSchema g : schema.goals().values()) {
			all.add(g.condition());
		}
		for (Expr root : all) {
			visit(root, false, comparisons);
		}
		boolean changed = true;
		while (changed) {
			changed = false;
			for (Expr.Compare c : comparisons) {
				if (readsQuantity(c.left()) || readsQuantity(c.right())) {
					changed |= addCalls(leaves(c.left())) | addCalls(leaves(c.right()));
				}
			}
		}
	}

	private void visit(Expr e, boolean inArith, List<Expr.Compare> comparisons) {
		if (e instanceof Expr.Arith a) {
			if (!inArith) {
				addCalls(leaves(a));
			}
			visit(a.left(), true, comparisons);
			visit(a.right(), true, comparisons);
		} else if (e instanceof Expr.And a) {
			visit(a.left(), false, comparisons);
			visit(a.right(), false, comparisons);
		} else if (e instanceof Expr.Or o) {
			visit(o.left(), false, comparisons);
			visit(o.right(), false, comparisons);
		} else if (e instanceof Expr.Not n) {
			visit(n.operand(), false, comparisons);
		} else if (e instanceof Expr.Compare c) {
			comparisons.add(c);
			visit(c.left(), false, comparisons);
			visit(c.right(), false, comparisons);
		} else if (e instanceof Expr.Call c) {
			for (Expr arg : c.args()) {
				visit(arg, false, comparisons);
			}
		}
	}

	boolean isQuantity(Expr.Call c) {
		return quantities.contains(key(c));
	}

	boolean isQuantity(String actor, String property) {
		return quantities.contains(actor + "." + property);
	}

	/**
	 * Whether an action sets a quantity (a battery drained, a load carried): only then can reaching one goal
	 * leave too little for the next. Quantities only charged as costs or read (distances) cannot.
	 */
	boolean anyChanged() {
		return schema.actions().stream().flatMap(a -> a.effects().stream()).anyMatch(e -> e.isAssignment() && isQuantity(e.call()));
	}

	boolean any() {
		return !quantities.isEmpty();
	}

	/** Whether a numeric expression is one the planner computes: arithmetic, or it reads a quantity. */
	boolean isNumericTerm(Expr e) {
		return e instanceof Expr.Arith || e instanceof Expr.Call c && isQuantity(c);
	}

	boolean readsQuantity(Expr e) {
		return leaves(e).stream().anyMatch(l -> l instanceof Expr.Call c && isQuantity(c));
	}

	private boolean addCalls(List<Expr> leaves) {
		boolean changed = false;
		for (Expr l : leaves) {
			if (l instanceof Expr.Call c && isNumeric(c)) {
				changed |= quantities.add(key(c));
			}
		}
		return changed;
	}

	private boolean isNumeric(Expr.Call c) {
		return schema.property(c.actor(), c.property()).map(p -> p.type().equals("int") || p.type().equals("double")).orElse(false);
	}

	/** The operands arithmetic combines (a call's arguments are objects, not operands). */
	static List<Expr> leaves(Expr e) {
		List<Expr> out = new ArrayList<>();
		collect(e, out);
		return out;
	}

	private static void collect(Expr e, List<Expr> out) {
		if (e instanceof Expr.Arith a) {
			collect(a.left(), out);
			collect(a.right(), out);
		} else {
			out.add(e);
		}
	}

	private static String key(Expr.Call c) {
		return c.actor() + "." + c.property();
	}
}
