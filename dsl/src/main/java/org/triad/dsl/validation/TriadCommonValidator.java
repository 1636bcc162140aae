package org.triad.dsl.validation;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.eclipse.xtext.EcoreUtil2;
import org.triad.dsl.app.ApplicationStructure;
import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.NamedElement;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.TriadPackage;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

import com.google.inject.Inject;

/**
 * Checks shared by every Triad language: the type rules of expressions, parameters, and names
 * that must be unique in the whole application. Each language's validator extends this one.
 */
public class TriadCommonValidator extends AbstractTriadCommonValidator {
	protected static final TriadPackage P = TriadPackage.eINSTANCE;

	@Inject
	private ResourceDescriptionsProvider indexProvider;

	@Inject
	private IQualifiedNameProvider names;

	@Check
	public void checkOperands(BinaryExpression e) {
		TriadType left = TriadTypeSystem.typeOf(e.getLeft());
		TriadType right = TriadTypeSystem.typeOf(e.getRight());
		switch (e.getOperator()) {
			case AND, OR -> {
				requireBoolean(e.getLeft(), left, e.getOperator().getLiteral(), P.getBinaryExpression_Left(), e);
				requireBoolean(e.getRight(), right, e.getOperator().getLiteral(), P.getBinaryExpression_Right(), e);
			}
			case EQ, NE -> {
				if (!TriadTypeSystem.isComparable(left, right) && !isEffect(e)) {
					error("cannot compare " + left.displayAgainst(right) + " with " + right.displayAgainst(left) + " using '" + e.getOperator().getLiteral() + "'",
							e, P.getBinaryExpression_Operator(), CommonIssueCodes.INCOMPATIBLE_OPERANDS);
				}
			}
			case LT, LE, GT, GE -> {
				if (!left.isNumeric() || !right.isNumeric()) {
					error("'" + e.getOperator().getLiteral() + "' compares numbers, not " + left.display() + " and " + right.display(),
							e, P.getBinaryExpression_Operator(), CommonIssueCodes.NOT_NUMERIC);
				}
			}
			case PLUS, MINUS, TIMES, DIVIDE -> checkArithmetic(e, left, right);
		}
	}

	private void checkArithmetic(BinaryExpression e, TriadType left, TriadType right) {
		String op = e.getOperator().getLiteral();
		for (Expression operand : List.of(e.getLeft(), e.getRight())) {
			TriadType t = TriadTypeSystem.typeOf(operand);
			if (!t.isNumeric()) {
				error("'" + sourceText(operand) + "' is " + article(t.display()) + " " + t.display() + ": '" + op + "' "
						+ ARITHMETIC_VERB.get(e.getOperator()) + " numbers (int or double)", e, P.getBinaryExpression_Operator(),
						CommonIssueCodes.NOT_NUMERIC);
				return;
			}
		}
		org.triad.dsl.semantics.ConstantArithmetic.Folded folded = org.triad.dsl.semantics.ConstantArithmetic.fold(e);
		org.triad.dsl.semantics.ConstantArithmetic.Folded divisor = org.triad.dsl.semantics.ConstantArithmetic.fold(e.getRight());
		if (folded.divisionByZero() || e.getOperator() == org.triad.dsl.triad.BinaryOperator.DIVIDE && divisor.isConstant() && divisor.value() == 0) {
			error("'" + sourceText(e) + "' divides by zero", e, P.getBinaryExpression_Right(), CommonIssueCodes.DIVISION_BY_ZERO);
		} else if (folded.overflow()) {
			error("'" + sourceText(e) + "' is too large for " + article(TriadTypeSystem.typeOf(e).display()) + " "
					+ TriadTypeSystem.typeOf(e).display() + (TriadTypeSystem.typeOf(e).kind() == TriadType.Kind.INT
							? " (at most 2147483647; write a decimal such as 3000000000.0 for a double)" : ""),
					e, P.getBinaryExpression_Operator(), CommonIssueCodes.OVERFLOW);
		}
	}

	/** A decimal beyond a double's range reads as infinity, which no battery or distance is: refused as arithmetic that overflows. */
	@Check
	public void checkDecimal(org.triad.dsl.triad.DecimalLiteral d) {
		if (Double.isInfinite(d.getValue())) {
			String text = sourceText(d);
			error("'" + (text.length() > 24 ? text.substring(0, 20) + "..." : text) + "' (" + text.indexOf('.') + " digits before the point) is too large"
					+ " for a double (at most about 1.8E308)", d, P.getDecimalLiteral_Value(), CommonIssueCodes.OVERFLOW);
		}
	}

	/** {@code -x} negates a number; a literal's negation is checked like other arithmetic on literals. */
	@Check
	public void checkNegation(org.triad.dsl.triad.NegationExpression e) {
		TriadType t = TriadTypeSystem.typeOf(e.getOperand());
		if (!t.isNumeric()) {
			if (!t.isUnknown()) {
				error("'" + sourceText(e.getOperand()) + "' is " + article(t.display()) + " " + t.display() + ": '-' negates numbers (int or double)"
						+ (t.isBoolean() ? "; '!' negates a condition" : ""), e, P.getNegationExpression_Operand(), CommonIssueCodes.NOT_NUMERIC);
			}
		}
		// no overflow of its own: an int literal is at most 2147483647, and -2147483647 is an int
	}

	private static final java.util.Map<org.triad.dsl.triad.BinaryOperator, String> ARITHMETIC_VERB = java.util.Map.of(
			org.triad.dsl.triad.BinaryOperator.PLUS, "adds", org.triad.dsl.triad.BinaryOperator.MINUS, "subtracts",
			org.triad.dsl.triad.BinaryOperator.TIMES, "multiplies", org.triad.dsl.triad.BinaryOperator.DIVIDE, "divides");

	@Check
	public void checkQuantityArguments(Actor actor) {
		reportQuantityArguments(actor);
	}

	@Check
	public void checkQuantityArguments(Goal goal) {
		reportQuantityArguments(goal);
	}

	/**
	 * The application's quantities, computed once per validation of a resource (they depend on every model of
	 * the application, so computing them per element would make checking quadratic in the model's size).
	 */
	protected org.triad.dsl.semantics.Quantities quantities(EObject element) {
		java.util.Map<Object, Object> context = getContext();
		if (context == null) {
			return org.triad.dsl.semantics.Quantities.of(element);
		}
		return (org.triad.dsl.semantics.Quantities) context.computeIfAbsent(org.triad.dsl.semantics.Quantities.class,
				k -> org.triad.dsl.semantics.Quantities.of(element));
	}

	/** A quantity is a number the planner computes with (a numeric fluent), not an object a property can take. */
	private void reportQuantityArguments(EObject root) {
		List<PropertyCall> calls = EcoreUtil2.getAllContentsOfType(root, PropertyCall.class);
		if (calls.stream().allMatch(c -> c.getArguments().isEmpty())) {
			return;
		}
		org.triad.dsl.semantics.Quantities q = quantities(root);
		for (PropertyCall call : calls) {
			if (call.getProperty() == null) {
				continue;
			}
			for (int i = 0; i < call.getArguments().size(); i++) {
				Expression argument = call.getArguments().get(i);
				if (TriadTypeSystem.isArithmetic(argument) && !Postconditions.isValue(argument)) {
					Expression arithmetic = argument;
					error("'" + sourceText(arithmetic) + "' is computed by arithmetic and cannot be the argument of '" + call.getProperty().getName()
							+ "': the planner passes objects and values as arguments; compare the number instead", call,
							P.getPropertyCall_Arguments(), i, CommonIssueCodes.QUANTITY_AS_ARGUMENT);
				} else if (call.getArguments().get(i) instanceof PropertyCall inner && inner.getProperty() != null && q.isQuantity(inner.getProperty())) {
					error("'" + sourceText(inner) + "' is a quantity the planner computes with (a number that changes by arithmetic), and cannot be the argument of '"
							+ call.getProperty().getName() + "'; compare it instead, e.g. '" + sourceText(inner) + " > 0'",
							call, P.getPropertyCall_Arguments(), i, CommonIssueCodes.QUANTITY_AS_ARGUMENT);
				}
			}
		}
	}

	/** {@code p()@pre} reads the value before an action: only the value of a postcondition's effect has a "before". */
	@Check
	public void checkPre(PropertyCall call) {
		if (!call.isPre()) {
			return;
		}
		Action action = EcoreUtil2.getContainerOfType(call, Action.class);
		if (action != null && action.getPost() != null) {
			for (org.triad.dsl.semantics.PostconditionEffect effect : Postconditions.analyse(action.getPost()).effects()) {
				if (effect.value() != null && (effect.value() == call || EcoreUtil2.isAncestor(effect.value(), call))) {
					return;
				}
			}
		}
		error("'" + sourceText(call) + "' is the value before the action: '@pre' belongs in the value a postcondition sets, e.g. 'battery() == battery()@pre - 5'; elsewhere write '"
				+ sourceText(call).replace("@pre", "") + "'", call, P.getPropertyCall_Pre(), CommonIssueCodes.PRE_OUTSIDE_POSTCONDITION);
	}

	/** An assignment effect {@code f(args) == v} of a postcondition, whose value's type the actor rules check. */
	private static boolean isEffect(BinaryExpression e) {
		Action action = EcoreUtil2.getContainerOfType(e, Action.class);
		return action != null && action.getPost() != null && e.getLeft() instanceof PropertyCall
				&& Postconditions.conjuncts(action.getPost()).contains(e);
	}

	/** Whether an earlier parameter of the same owner has the same name (reported as a duplicate). */
	protected static boolean isDuplicate(Parameter p) {
		if (!(p.eContainer() instanceof Parameterized owner)) {
			return false;
		}
		for (Parameter other : owner.getParameters()) {
			if (other == p) {
				return false;
			}
			if (other.getName() != null && other.getName().equals(p.getName())) {
				return true;
			}
		}
		return false;
	}

	private void requireBoolean(Expression operand, TriadType type, String operator, EStructuralFeature feature, EObject owner) {
		if (!type.isBoolean()) {
			error(notACondition(operand, type, operator), owner, feature, CommonIssueCodes.NOT_BOOLEAN_OPERAND);
		}
	}

	/** Names the operand, what it is and how to make a condition of it (the operator joins or negates conditions). */
	private static String notACondition(Expression operand, TriadType type, String operator) {
		String text = sourceText(operand);
		String role = operator.equals("!") ? "'!' negates a condition" : "'" + operator + "' joins conditions";
		String example = type.isNumeric() ? text + " > 0" : text + " == " + (type.kind() == TriadType.Kind.STRING ? "\"...\"" : "value");
		return "'" + text + "' is " + article(type.display()) + " " + type.display() + ", not a condition (true or false): " + role
				+ "; compare it, e.g. '" + example + "'";
	}

	private static String article(String word) {
		return "aeiouAEIOU".indexOf(word.charAt(0)) >= 0 ? "an" : "a";
	}

	/** The expression as written, blanks collapsed. */
	protected static String sourceText(EObject e) {
		org.eclipse.xtext.nodemodel.ICompositeNode node = org.eclipse.xtext.nodemodel.util.NodeModelUtils.findActualNodeFor(e);
		return node == null ? "?" : org.eclipse.xtext.nodemodel.util.NodeModelUtils.getTokenText(node).replaceAll("\\s+", " ").trim();
	}

	@Check
	public void checkNotOperand(NotExpression e) {
		requireBoolean(e.getOperand(), TriadTypeSystem.typeOf(e.getOperand()), "!", P.getNotExpression_Operand(), e);
	}

	/**
	 * A Boolean property passed as an argument ({@code ready(handEmpty())}): the planner passes objects
	 * and values, and a condition is neither (situations report their arguments themselves).
	 */
	@Check
	public void checkConditionAsArgument(PropertyCall call) {
		if (EcoreUtil2.getContainerOfType(call, Situation.class) != null) {
			return;
		}
		Property p = call.getProperty();
		if (p == null || p.eIsProxy() || p.getParameters().size() != call.getArguments().size()) {
			return; // reported as an unknown property or a wrong number of arguments
		}
		for (int i = 0; i < call.getArguments().size(); i++) {
			// only where a boolean is expected: elsewhere the argument's type is the finding (expr.argument-type)
			if (call.getArguments().get(i) instanceof PropertyCall inner && TriadTypeSystem.typeOf(inner).kind() == TriadType.Kind.BOOLEAN
					&& TriadTypeSystem.typeOf(p.getParameters().get(i).getType()).kind() == TriadType.Kind.BOOLEAN) {
				String text = sourceText(inner);
				error("'" + text + "' is a condition and cannot be the argument of '" + p.getName()
						+ "': the planner passes objects and values only; give the action or goal a boolean parameter b, pass b, and require '"
						+ text + " == b'", call, P.getPropertyCall_Arguments(), i, CommonIssueCodes.CONDITION_AS_ARGUMENT);
			}
		}
	}

	@Check
	public void checkCallArguments(PropertyCall call) {
		Property p = call.getProperty();
		if (p == null || p.eIsProxy()) {
			return;
		}
		List<Parameter> params = p.getParameters();
		if (params.size() != call.getArguments().size()) {
			error("property '" + p.getName() + "' takes " + params.size() + " argument(s), but " + call.getArguments().size()
					+ " are given", call, P.getPropertyCall_Property(), CommonIssueCodes.ARGUMENT_COUNT);
			return;
		}
		for (int i = 0; i < params.size(); i++) {
			TriadType expected = TriadTypeSystem.typeOf(params.get(i).getType());
			TriadType actual = TriadTypeSystem.typeOf(call.getArguments().get(i));
			if (!TriadTypeSystem.isAssignable(expected, actual)) {
				error("argument " + (i + 1) + " of '" + p.getName() + "' must be " + expected.displayAgainst(actual) + ", but is "
						+ actual.displayAgainst(expected), call, P.getPropertyCall_Arguments(), i, CommonIssueCodes.ARGUMENT_TYPE);
			}
		}
	}

	@Check
	public void checkParameterNames(Parameterized owner) {
		Set<String> seen = new HashSet<>();
		for (Parameter p : owner.getParameters()) {
			if (p.getName() != null && !seen.add(p.getName())) {
				error("duplicate parameter '" + p.getName() + "' of '" + owner.getName() + "'", p, P.getNamedElement_Name(),
						CommonIssueCodes.DUPLICATE_PARAMETER);
			}
		}
	}

	/** Reports a condition that is not Boolean. */
	protected void requireCondition(Expression condition, String what, EObject owner, EStructuralFeature feature) {
		if (condition != null && !TriadTypeSystem.typeOf(condition).isBoolean()) {
			error(what + " must be a boolean condition, but is " + TriadTypeSystem.typeOf(condition).display(), owner, feature,
					CommonIssueCodes.CONDITION_NOT_BOOLEAN);
		}
	}

	@Check(CheckType.NORMAL)
	public void checkApplicationWideName(NamedElement element) {
		if (!(element instanceof ClassDiagram || element instanceof Actor || element instanceof Goal || element instanceof Task
				|| element instanceof Situation) || element.getName() == null || element.eResource() == null) {
			return;
		}
		QualifiedName name = names.getFullyQualifiedName(element);
		if (name == null) {
			return;
		}
		URI self = EcoreUtil.getURI(element);
		IResourceDescriptions index = indexProvider.getResourceDescriptions(element.eResource());
		for (IEObjectDescription other : index.getExportedObjects(P.getNamedElement(), name, false)) {
			if (!other.getEObjectURI().equals(self) && isApplicationLevel(other)) {
				error("duplicate name '" + element.getName() + "': a " + kind(other) + " in " + other.getEObjectURI().lastSegment()
						+ " has the same name", element, P.getNamedElement_Name(), CommonIssueCodes.DUPLICATE_NAME);
				return;
			}
		}
	}

	/**
	 * The application's structure rule ({@link ApplicationStructure}): one class diagram, one robot,
	 * one world among every model the index sees, reported on the element that breaks it.
	 */
	@Check(CheckType.NORMAL)
	public void checkApplicationStructure(ClassDiagram cd) {
		reportStructure(cd);
	}

	@Check(CheckType.NORMAL)
	public void checkApplicationStructure(Actor actor) {
		reportStructure(actor);
	}

	private void reportStructure(NamedElement element) {
		if (element.eResource() == null) {
			return;
		}
		IResourceDescriptions index = indexProvider.getResourceDescriptions(element.eResource());
		List<EObject> candidates = new ArrayList<>();
		for (EClass type : List.of(P.getClassDiagram(), P.getActor(), org.triad.dsl.arc.ArcPackage.Literals.COMPONENT_TYPE)) {
			for (IEObjectDescription d : index.getExportedObjectsByType(type)) {
				EObject resolved = EcoreUtil.resolve(d.getEObjectOrProxy(), element);
				if (!resolved.eIsProxy() && !candidates.contains(resolved)) {
					candidates.add(resolved);
				}
			}
		}
		if (!candidates.contains(element)) {
			candidates.add(element); // not indexed (e.g. a name with a syntax error): still part of the application
		}
		for (ApplicationStructure.Violation v : ApplicationStructure.of(candidates).violations()) {
			if (v.element() == element) {
				error(v.message(), element, P.getNamedElement_Name(), v.code());
			}
		}
	}

	private static boolean isApplicationLevel(IEObjectDescription d) {
		return d.getEClass() == P.getClassDiagram() || d.getEClass() == P.getActor() || d.getEClass() == P.getGoal()
				|| d.getEClass() == P.getTask() || d.getEClass() == P.getSituation();
	}

	private static String kind(IEObjectDescription d) {
		return d.getEClass() == P.getClassDiagram() ? "class diagram" : d.getEClass().getName().toLowerCase();
	}
}
