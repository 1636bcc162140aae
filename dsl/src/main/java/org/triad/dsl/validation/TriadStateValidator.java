package org.triad.dsl.validation;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.AttributeAssignment;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.BinaryOperator;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.semantics.SituationLineage;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

/** Rules of situations; codes in {@link StateIssueCodes}. */
public class TriadStateValidator extends AbstractTriadStateValidator {

	@Check
	public void checkObjects(Situation s) {
		Set<String> seen = new HashSet<>();
		for (ObjectDeclaration d : s.getDeclarations()) {
			for (SituationObject o : d.getObjects()) {
				if (o.getName() != null && !seen.add(o.getName())) {
					error("duplicate object '" + o.getName() + "' in state '" + s.getName() + "'", o, P.getNamedElement_Name(),
							StateIssueCodes.DUPLICATE_OBJECT);
				} else if (o.getName() != null) {
					inheritedFrom(s, o.getName()).ifPresent(owner -> error("object '" + o.getName() + "' is already declared in state '"
							+ owner + "', which '" + s.getName() + "' extends; change its facts instead of declaring it again", o,
							P.getNamedElement_Name(), StateIssueCodes.DUPLICATE_OBJECT));
				}
			}
		}
	}

	@Check
	public void checkParent(Situation s) {
		if (s.getParent() != null && !s.getParent().eIsProxy() && SituationLineage.extendsItself(s)) {
			error("state '" + s.getName() + "' extends itself through " + SituationLineage.lineage(s.getParent()).stream().map(Situation::getName).toList()
					+ "; a situation extends one that does not extend it", s, P.getSituation_Parent(), StateIssueCodes.EXTENDS_CYCLE);
		}
	}

	/** The ancestor situation that declares an object of this name, if any. */
	private static java.util.Optional<String> inheritedFrom(Situation s, String name) {
		List<Situation> lineage = SituationLineage.lineage(s);
		for (Situation ancestor : lineage.subList(1, lineage.size())) {
			for (ObjectDeclaration d : ancestor.getDeclarations()) {
				for (SituationObject o : d.getObjects()) {
					if (name.equals(o.getName())) {
						return java.util.Optional.of(ancestor.getName());
					}
				}
			}
		}
		return java.util.Optional.empty();
	}

	@Check
	public void checkDeclaration(ObjectDeclaration d) {
		if (d.getType() != null && !d.getType().eIsProxy() && d.getType().isAbstract()) {
			error("class '" + d.getType().getName() + "' is abstract and has no objects of its own", d, P.getObjectDeclaration_Type(),
					StateIssueCodes.ABSTRACT_OBJECT);
		}
	}

	@Check
	public void checkAssignments(SituationObject o) {
		Set<String> seen = new HashSet<>();
		for (AttributeAssignment a : o.getAssignments()) {
			if (a.getAttribute() == null || a.getAttribute().eIsProxy()) {
				continue;
			}
			if (!seen.add(a.getAttribute().getName())) {
				error("attribute '" + a.getAttribute().getName() + "' of '" + o.getName() + "' is given twice", a,
						P.getAttributeAssignment_Attribute(), StateIssueCodes.DUPLICATE_ATTRIBUTE);
			}
			TriadType expected = TriadTypeSystem.typeOf(a.getAttribute().getType());
			TriadType actual = TriadTypeSystem.typeOf(a.getValue());
			if (!Postconditions.isValue(a.getValue()) || a.getValue() instanceof ValueRef && !(expected.kind() == TriadType.Kind.CLASS)
					|| !TriadTypeSystem.isAssignable(expected, actual)) {
				error("attribute '" + a.getAttribute().getName() + "' takes a " + expected.display() + " literal", a,
						P.getAttributeAssignment_Value(), StateIssueCodes.ATTRIBUTE_VALUE);
			}
		}
	}

	@Check
	public void checkFacts(Situation s) {
		Map<String, String> values = new HashMap<>();
		for (int i = 0; i < s.getFacts().size(); i++) {
			Expression fact = s.getFacts().get(i);
			PropertyCall call;
			Expression value = null;
			if (fact instanceof PropertyCall c && TriadTypeSystem.typeOf(c).isBoolean()) {
				call = c;
			} else if (fact instanceof NotExpression not && not.getOperand() instanceof PropertyCall c && TriadTypeSystem.typeOf(c).isBoolean()
					&& s.getParent() != null) {
				call = c; // retracts an inherited fact (state B extends A)
			} else if (fact instanceof BinaryExpression b && b.getOperator() == BinaryOperator.EQ && b.getLeft() instanceof PropertyCall c
					&& TriadTypeSystem.typeOf(c).kind() != TriadType.Kind.BOOLEAN) {
				call = c;
				value = b.getRight();
			} else {
				error("a fact is 'Actor.p(objects)' for a boolean property or 'Actor.f(objects) == value' for another property"
						+ " (closed world: what is not stated does not hold; '!Actor.p(objects)' retracts a fact in a state that extends another)", s, P.getSituation_Facts(), i, StateIssueCodes.FACT_KIND);
				continue;
			}
			for (Expression arg : call.getArguments()) {
				if (!Postconditions.isValue(arg)) {
					error("arguments of a fact are objects of the state or literals", call, P.getPropertyCall_Arguments(),
							call.getArguments().indexOf(arg), StateIssueCodes.FACT_ARGUMENT);
				}
			}
			if (value != null) {
				org.triad.dsl.semantics.ConstantArithmetic.Folded folded = org.triad.dsl.semantics.ConstantArithmetic.fold(value);
				boolean arithmetic = folded.isConstant() || folded.divisionByZero() || folded.overflow(); // the last two: expr.division-by-zero, expr.overflow
				if (!Postconditions.isValue(value) && !arithmetic) {
					error("the value of a fact is an object of the state, a literal, or arithmetic on literals", fact, P.getBinaryExpression_Right(),
							StateIssueCodes.FACT_ARGUMENT);
					continue;
				}
				String key = text(call);
				String previous = values.put(key, text(value));
				if (previous != null && !previous.equals(text(value))) {
					error("'" + key + "' is " + previous + " and " + text(value) + " at once", fact, P.getBinaryExpression_Right(),
							StateIssueCodes.CONFLICTING_VALUE);
				}
			}
		}
	}

	/**
	 * A number the planner computes with is a numeric fluent, and one without a value makes every action
	 * that reads it inapplicable, silently (PDDL 2.1's undefined value): the goal is then unreachable "even
	 * when nothing is ever deleted", which names no cause. A quantity without arguments (a battery, a
	 * payload limit) has one value per situation, so leaving it out is a mistake; one with arguments (a
	 * distance between two places) is stated for the pairs it exists for only, so it is not checked.
	 */
	@Check
	public void checkQuantitiesStated(Situation s) {
		if (s.eResource() == null || s.eResource().getResourceSet() == null || SituationLineage.extendsItself(s)) {
			return;
		}
		org.triad.dsl.semantics.Quantities quantities = org.triad.dsl.semantics.Quantities.of(s);
		Set<String> stated = new HashSet<>();
		for (Situation ancestor : SituationLineage.lineage(s)) {
			for (Expression fact : ancestor.getFacts()) {
				if (fact instanceof BinaryExpression b && b.getOperator() == BinaryOperator.EQ && b.getLeft() instanceof PropertyCall c
						&& c.getArguments().isEmpty() && c.getActor() != null && !c.getActor().eIsProxy()) {
					stated.add(c.getActor().getName() + "." + c.getProperty().getName());
				}
			}
		}
		for (org.eclipse.emf.ecore.resource.Resource r : List.copyOf(s.eResource().getResourceSet().getResources())) {
			for (org.eclipse.emf.ecore.EObject root : r.getContents()) {
				if (!(root instanceof org.triad.dsl.triad.ActorModel m) || m.getActor() == null) {
					continue;
				}
				for (org.triad.dsl.triad.Property p : m.getActor().getProperties()) {
					String name = m.getActor().getName() + "." + p.getName();
					if (p.getParameters().isEmpty() && quantities.isQuantity(p) && !stated.contains(name)) {
						error("state '" + s.getName() + "' gives no value to " + name + "(), a number the models compute with, so no action that"
								+ " reads it could ever apply; state it, e.g. '" + name + "() == ...;'", s, P.getNamedElement_Name(),
								StateIssueCodes.UNDEFINED_QUANTITY);
					}
				}
			}
		}
		for (ObjectDeclaration d : s.getDeclarations()) {
			if (d.getType() == null || d.getType().eIsProxy()) {
				continue;
			}
			for (SituationObject o : d.getObjects()) {
				Set<String> given = new HashSet<>();
				o.getAssignments().forEach(a -> given.add(a.getAttribute() == null || a.getAttribute().eIsProxy() ? "" : a.getAttribute().getName()));
				Set<org.triad.dsl.triad.DomainClass> seen = new HashSet<>(); // cd.cyclic-inheritance is reported elsewhere
				for (org.triad.dsl.triad.DomainClass c = d.getType(); c != null && !c.eIsProxy() && seen.add(c); c = c.getSuperType()) {
					for (org.triad.dsl.triad.Attribute a : c.getAttributes()) {
						if (quantities.isQuantity(a) && !given.contains(a.getName())) {
							error(d.getType().getName() + " " + o.getName() + " has no " + a.getName() + ", an attribute of " + c.getName()
									+ " the models compute with, so no action that reads it could ever apply; give it one, e.g. '"
									+ d.getType().getName() + " " + o.getName() + " { " + a.getName() + " = ...; };'", o, P.getNamedElement_Name(),
									StateIssueCodes.UNDEFINED_QUANTITY);
						}
					}
				}
			}
		}
	}

	private static String text(Expression e) {
		return NodeModelUtils.getTokenText(NodeModelUtils.findActualNodeFor(e)).replaceAll("\\s+", "");
	}
}
