package org.triad.dsl.validation;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.triad.dsl.semantics.PostconditionEffect;
import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.NamedElement;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

/** Rules of robot and world actors; codes in {@link ActorIssueCodes}. */
public class TriadActorValidator extends AbstractTriadActorValidator {
	@Check
	public void checkUniqueMembers(Actor actor) {
		Set<String> seen = new HashSet<>();
		for (NamedElement member : concat(actor)) {
			if (member.getName() != null && !seen.add(member.getName())) {
				error("duplicate member '" + member.getName() + "' of actor '" + actor.getName() + "'", member,
						P.getNamedElement_Name(), ActorIssueCodes.DUPLICATE_MEMBER);
			}
		}
	}

	private static Iterable<NamedElement> concat(Actor actor) {
		java.util.List<NamedElement> all = new java.util.ArrayList<>(actor.getProperties());
		all.addAll(actor.getActions());
		return all;
	}

	@Check
	public void checkPrecondition(Action action) {
		requireCondition(action.getPre(), "precondition of '" + action.getName() + "'", action, P.getAction_Pre());
	}

	@Check
	public void checkPostcondition(Action action) {
		Postconditions.Analysis analysis = Postconditions.analyse(action.getPost());
		for (Postconditions.Problem problem : analysis.problems()) {
			EObject at = problem.expression();
			error(problem.message(), at.eContainer(), at.eContainmentFeature(), indexIn(at),
					analysisCode(problem), new String[0]);
		}
		Map<String, PostconditionEffect> byTarget = new HashMap<>();
		for (PostconditionEffect effect : analysis.effects()) {
			if (effect.isAssignment()) {
				TriadType target = TriadTypeSystem.typeOf(effect.call());
				TriadType value = TriadTypeSystem.typeOf(effect.value());
				if (!TriadTypeSystem.isAssignable(target, value)) {
					error("'" + effect.call().getProperty().getName() + "' is " + target.display() + " and cannot be assigned "
							+ value.display(), effect.value().eContainer(), effect.value().eContainmentFeature(),
							ActorIssueCodes.EFFECT_VALUE);
				}
			}
			String key = targetKey(effect.call(), action);
			PostconditionEffect previous = byTarget.put(key, effect);
			if (previous != null) {
				error("the postcondition of '" + action.getName() + "' sets '" + key + "' twice", effect.call().eContainer(),
						effect.call().eContainmentFeature(), ActorIssueCodes.CONFLICTING_EFFECTS);
			}
		}
	}

	/**
	 * A property the action changes, read in the value of an effect, is written with {@code @pre}: without it,
	 * {@code battery() == battery() - 5} would say the battery after is 5 less than itself. Properties the
	 * action does not change read the same before and after, so {@code - Building.distance(src, dst)} needs none.
	 */
	@Check
	public void checkEffectReadsBefore(Action action) {
		java.util.List<PostconditionEffect> all = Postconditions.analyse(action.getPost()).effects();
		Set<Property> changed = new HashSet<>();
		for (PostconditionEffect effect : all) {
			changed.add(effect.call().getProperty());
		}
		for (PostconditionEffect effect : all) {
			if (effect.value() == null || !Postconditions.isArithmeticValue(effect.value())) {
				continue;
			}
			java.util.List<PropertyCall> reads = new java.util.ArrayList<>();
			if (effect.value() instanceof PropertyCall c) {
				reads.add(c);
			}
			reads.addAll(EcoreUtil2.getAllContentsOfType(effect.value(), PropertyCall.class));
			for (PropertyCall read : reads) {
				if (!read.isPre() && changed.contains(read.getProperty())) {
					String text = sourceText(read);
					error("'" + text + "' in a postcondition is the value after the action, which sets it; write '" + text
							+ "@pre' for the value before it, e.g. '" + text + " == " + text + "@pre - 5'", read,
							P.getPropertyCall_Property(), ActorIssueCodes.EFFECT_NEEDS_PRE);
				}
			}
		}
	}

	@Check
	public void checkCost(Action action) {
		if (action.getCost() != null) {
			TriadType t = TriadTypeSystem.typeOf(action.getCost());
			if (!t.isNumeric()) {
				error("the cost of '" + action.getName() + "' must be a number (what one execution costs, e.g. 'Building.distance(src, dst)'), but is "
						+ t.display(), action, P.getAction_Cost(), ActorIssueCodes.COST_NOT_NUMERIC);
			}
		}
	}

	/**
	 * Numeric planning (PDDL 2.1, Metric-FF) chooses objects for an action's parameters, never numbers: a
	 * number parameter cannot be combined with a quantity, which the planner computes with.
	 */
	@Check
	public void checkQuantities(Actor actor) {
		org.triad.dsl.semantics.Quantities q = quantities(actor);
		Set<EObject> reported = new HashSet<>();
		for (Action action : actor.getActions()) {
			java.util.List<org.triad.dsl.triad.Expression> contexts = new java.util.ArrayList<>();
			if (action.getCost() != null) {
				contexts.add(action.getCost());
			}
			for (org.triad.dsl.triad.Expression root : java.util.Arrays.asList(action.getPre(), action.getPost())) {
				if (root == null) {
					continue;
				}
				java.util.List<EObject> all = new java.util.ArrayList<>(java.util.List.of(root));
				root.eAllContents().forEachRemaining(all::add);
				for (EObject o : all) {
					if (o instanceof org.triad.dsl.triad.BinaryExpression b && b.getOperator() != org.triad.dsl.triad.BinaryOperator.AND
							&& b.getOperator() != org.triad.dsl.triad.BinaryOperator.OR
							&& !(b.eContainer() instanceof org.triad.dsl.triad.BinaryExpression outer
									&& TriadTypeSystem.isArithmetic(outer.getOperator()))
							&& (q.readsQuantity(b.getLeft()) || q.readsQuantity(b.getRight())
									|| b.getLeft() instanceof PropertyCall c && c.getProperty() != null && q.isQuantity(c.getProperty()))) {
						contexts.add(b);
					}
				}
			}
			for (org.triad.dsl.triad.Expression context : contexts) {
				java.util.List<org.triad.dsl.triad.Expression> leaves = new java.util.ArrayList<>();
				if (context instanceof org.triad.dsl.triad.BinaryExpression b && !TriadTypeSystem.isArithmetic(b.getOperator())) {
					leaves.addAll(org.triad.dsl.semantics.Quantities.leaves(b.getLeft()));
					leaves.addAll(org.triad.dsl.semantics.Quantities.leaves(b.getRight()));
				} else {
					leaves.addAll(org.triad.dsl.semantics.Quantities.leaves(context));
				}
				for (org.triad.dsl.triad.Expression leaf : leaves) {
					if (leaf instanceof org.triad.dsl.triad.ValueRef v && v.getValue() instanceof org.triad.dsl.triad.Parameter p
							&& TriadTypeSystem.typeOf(p.getType()).kind() != TriadType.Kind.UNKNOWN && TriadTypeSystem.typeOf(p.getType()).isNumeric()
							&& reported.add(v)) {
						error("'" + p.getName() + "' is a number parameter of '" + action.getName()
								+ "' used with a quantity the planner computes with: numeric planning chooses objects for parameters, not numbers; use a literal, or a property of an object parameter (e.g. 'Building.weight(i)')",
								v, P.getValueRef_Value(), org.triad.dsl.validation.CommonIssueCodes.NUMBER_PARAMETER);
					}
				}
			}
		}
	}

	/**
	 * What an effect changes: the property (whether named as {@code p()} or {@code Actor.p()}) and
	 * its arguments as written.
	 */
	private static String targetKey(PropertyCall call, Action action) {
		Property p = call.getProperty();
		if (p == null || p.eIsProxy() || !(p.eContainer() instanceof Actor owner)) {
			return text(call);
		}
		StringBuilder key = new StringBuilder();
		if (owner != EcoreUtil2.getContainerOfType(action, Actor.class)) {
			key.append(owner.getName()).append('.');
		}
		key.append(p.getName()).append('(');
		for (int i = 0; i < call.getArguments().size(); i++) {
			key.append(i == 0 ? "" : ", ").append(text(call.getArguments().get(i)));
		}
		return key.append(')').toString();
	}

	private static String text(EObject e) {
		if (e == null || NodeModelUtils.findActualNodeFor(e) == null) {
			return "?";
		}
		return NodeModelUtils.getTokenText(NodeModelUtils.findActualNodeFor(e)).replaceAll("\\s+", "");
	}

	private static int indexIn(EObject e) {
		Object value = e.eContainer().eGet(e.eContainmentFeature());
		return value instanceof java.util.List<?> list ? list.indexOf(e) : -1;
	}

	private static String analysisCode(Postconditions.Problem problem) {
		return problem.badValue() ? ActorIssueCodes.EFFECT_VALUE : ActorIssueCodes.POST_NOT_EFFECT;
	}
}
