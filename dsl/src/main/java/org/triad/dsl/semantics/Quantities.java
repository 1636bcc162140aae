package org.triad.dsl.semantics;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.eclipse.xtext.EcoreUtil2;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.BinaryOperator;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * Which numeric properties are <em>quantities</em>: numbers the planner computes with (a battery level, a
 * distance, a load), planned as numeric fluents of PDDL 2.1 as Metric-FF plans them. A numeric property is
 * a quantity when the models do arithmetic with it, charge it as a cost, set it from arithmetic or from
 * another property ({@code battery() == battery()@pre - 5}), or compare it with a quantity. Other numeric
 * properties stay values that are compared as they are. The runtime's translation applies the same rule to
 * the application's schema ({@code org.triad.runtime.schema.Quantities}).
 */
public final class Quantities {
	/** Properties, and attributes read as {@code i.weight}. */
	private final Set<EObject> quantities = new LinkedHashSet<>();

	private Quantities() {
	}

	/** The quantities of the application whose models are loaded in {@code context}'s resource set. */
	public static Quantities of(EObject context) {
		List<Action> actions = new ArrayList<>();
		List<Goal> goals = new ArrayList<>();
		ResourceSet set = context.eResource() == null ? null : context.eResource().getResourceSet();
		List<Resource> resources = set == null ? context.eResource() == null ? List.of() : List.of(context.eResource()) : List.copyOf(set.getResources());
		for (Resource r : resources) {
			for (EObject root : r.getContents()) {
				actions.addAll(EcoreUtil2.getAllContentsOfType(root, Action.class));
				goals.addAll(EcoreUtil2.getAllContentsOfType(root, Goal.class));
			}
		}
		Quantities q = new Quantities();
		q.compute(actions, goals);
		return q;
	}

	public boolean isQuantity(Property p) {
		return quantities.contains(p);
	}

	/** Whether the models compute with an attribute ({@code i.weight} in arithmetic, a cost or a comparison with a quantity). */
	public boolean isQuantity(org.triad.dsl.triad.Attribute a) {
		return quantities.contains(a);
	}

	/** Whether a numeric expression reads a quantity (directly or through arithmetic). */
	public boolean readsQuantity(Expression e) {
		return leaves(e).stream().anyMatch(l -> quantities.contains(read(l)));
	}

	private void compute(List<Action> actions, List<Goal> goals) {
		List<Expression> all = new ArrayList<>();
		for (Action a : actions) {
			add(all, a.getPre());
			add(all, a.getPost());
			if (a.getCost() != null) {
				addCalls(leaves(a.getCost()));
				all.add(a.getCost());
			}
			for (PostconditionEffect effect : Postconditions.analyse(a.getPost()).effects()) {
				if (effect.isAssignment() && isNumeric(effect.value()) && !(effect.value() instanceof ValueRef)
						&& !Postconditions.isValue(effect.value())) {
					quantities.add(effect.call().getProperty());
					addCalls(leaves(effect.value()));
				}
			}
		}
		for (Goal g : goals) {
			add(all, g.getCondition());
		}
		List<BinaryExpression> comparisons = new ArrayList<>();
		for (Expression root : all) {
			for (EObject o : iterable(root)) {
				if (o instanceof Expression a && TriadTypeSystem.isArithmetic(a)
						&& !(a.eContainer() instanceof Expression outer && TriadTypeSystem.isArithmetic(outer))) {
					addCalls(leaves(a));
				} else if (o instanceof BinaryExpression b && isComparison(b.getOperator())) {
					comparisons.add(b);
				}
			}
		}
		boolean changed = true;
		while (changed) { // a number compared with a quantity is one too
			changed = false;
			for (BinaryExpression b : comparisons) {
				if (readsQuantity(b.getLeft()) || readsQuantity(b.getRight())) {
					changed |= addCalls(leaves(b.getLeft())) | addCalls(leaves(b.getRight()));
				}
			}
		}
	}

	private static Iterable<EObject> iterable(Expression root) {
		List<EObject> out = new ArrayList<>();
		out.add(root);
		root.eAllContents().forEachRemaining(out::add);
		return out;
	}

	private static void add(List<Expression> all, Expression e) {
		if (e != null) {
			all.add(e);
		}
	}

	private boolean addCalls(List<Expression> leaves) {
		boolean changed = false;
		for (Expression l : leaves) {
			EObject read = read(l);
			if (read != null && !read.eIsProxy() && isNumeric(l)) {
				changed |= quantities.add(read);
			}
		}
		return changed;
	}

	/** The property a call reads, or the attribute {@code i.weight} reads; null for other expressions. */
	private static EObject read(Expression e) {
		if (e instanceof PropertyCall c) {
			return c.getProperty();
		}
		return e instanceof org.triad.dsl.triad.MemberRef r && r.getMember() instanceof org.triad.dsl.triad.Attribute a ? a : null;
	}

	/**
	 * The operands arithmetic combines: property calls, parameters and literals below {@code + - * /}
	 * (a call's arguments are objects, not operands).
	 */
	public static List<Expression> leaves(Expression e) {
		List<Expression> out = new ArrayList<>();
		collectLeaves(e, out);
		return out;
	}

	private static void collectLeaves(Expression e, List<Expression> out) {
		if (e instanceof BinaryExpression b && TriadTypeSystem.isArithmetic(b.getOperator())) {
			collectLeaves(b.getLeft(), out);
			collectLeaves(b.getRight(), out);
		} else if (e instanceof org.triad.dsl.triad.NegationExpression n) {
			collectLeaves(n.getOperand(), out);
		} else if (e != null) {
			out.add(e);
		}
	}

	private static boolean isNumeric(Expression e) {
		var t = TriadTypeSystem.typeOf(e);
		return !t.isUnknown() && t.isNumeric();
	}

	private static boolean isComparison(BinaryOperator op) {
		return op == BinaryOperator.EQ || op == BinaryOperator.NE || op == BinaryOperator.LT || op == BinaryOperator.LE
				|| op == BinaryOperator.GT || op == BinaryOperator.GE;
	}
}
