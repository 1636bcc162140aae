package org.triad.dsl.validation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.eclipse.xtext.validation.Check;
import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.arc.Assignment;
import org.triad.dsl.arc.ConfigParameter;
import org.triad.dsl.arc.ExpressionStatement;
import org.triad.dsl.arc.MemberAccess;
import org.triad.dsl.arc.NewInstance;
import org.triad.dsl.arc.Statement;
import org.triad.dsl.arc.Transition;
import org.triad.dsl.arc.Variable;
import org.triad.dsl.arc.ArcPackage;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Connector;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.arc.PortRef;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.typing.ArcExpressionTypes;
import org.triad.dsl.typing.ArcTypes;

import com.google.inject.Inject;

/** Rules of architecture models; codes in {@link ArcIssueCodes}. */
public class TriadArcValidator extends AbstractTriadArcValidator {
	private static final ArcPackage A = ArcPackage.eINSTANCE;

	@Inject
	private ResourceDescriptionsProvider indexProvider;

	@Inject
	private IQualifiedNameProvider names;

	/** Parameters, ports and subcomponents share one namespace: each becomes a field of the generated class. */
	@Check
	public void checkUniqueMemberNames(ComponentType c) {
		Map<String, ArcNamedElement> seen = new HashMap<>();
		List<ArcNamedElement> members = new ArrayList<>();
		members.addAll(c.getParameters());
		members.addAll(ArcModels.ports(c));
		members.addAll(ArcModels.subcomponents(c));
		members.addAll(c.getVariables());
		for (ArcNamedElement m : members) {
			if (m.getName() == null) {
				continue;
			}
			ArcNamedElement first = seen.putIfAbsent(m.getName(), m);
			if (first != null) {
				error("duplicate name '" + m.getName() + "' in component '" + c.getName() + "': already a " + kind(first), m,
						A.getArcNamedElement_Name(), ArcIssueCodes.DUPLICATE_NAME);
			}
		}
	}

	@Check
	public void checkUniqueComponent(ComponentType c) {
		QualifiedName name = names.getFullyQualifiedName(c);
		if (name == null || c.eResource() == null) {
			return;
		}
		URI self = EcoreUtil.getURI(c);
		IResourceDescriptions index = indexProvider.getResourceDescriptions(c.eResource());
		for (IEObjectDescription other : index.getExportedObjects(A.getComponentType(), name, false)) {
			if (!other.getEObjectURI().equals(self)) {
				error("duplicate component '" + name + "': also declared in " + other.getEObjectURI().trimFragment().lastSegment(), c,
						A.getArcNamedElement_Name(), ArcIssueCodes.DUPLICATE_NAME);
				return;
			}
		}
	}

	@Check
	public void checkConnectorsNeedSubcomponents(ComponentType c) {
		if (ArcModels.isComposed(c)) {
			return;
		}
		for (Connector connector : c.getConnectors()) {
			error("atomic component '" + c.getName() + "' has no subcomponents, so it cannot have connectors", connector, null,
					ArcIssueCodes.CONNECTOR_IN_ATOMIC);
		}
	}

	@Check
	public void checkConnectors(ComponentType c) {
		if (!ArcModels.isComposed(c)) {
			return;
		}
		Map<String, PortRef> senders = new HashMap<>();
		for (Connector connector : c.getConnectors()) {
			Endpoint source = Endpoint.of(connector.getSource());
			if (source != null && !source.canSend()) {
				error("connector source " + source.describe() + " cannot send here: a source must be an incoming port of '"
						+ c.getName() + "' or an outgoing port of a subcomponent", connector.getSource(), null,
						ArcIssueCodes.DIRECTION_MISMATCH);
			}
			for (PortRef targetRef : connector.getTargets()) {
				Endpoint target = Endpoint.of(targetRef);
				if (target == null) {
					continue;
				}
				if (!target.canReceive()) {
					error("connector target " + target.describe() + " cannot receive here: a target must be an outgoing port of '"
							+ c.getName() + "' or an incoming port of a subcomponent", targetRef, null, ArcIssueCodes.DIRECTION_MISMATCH);
				}
				if (source != null && source.type() != null && target.type() != null && !ArcTypes.isAssignable(source.type(), target.type())) {
					error("type mismatch: " + source.describe() + " sends " + source.type() + " but " + target.describe()
							+ " takes " + target.type(), targetRef, null, ArcIssueCodes.TYPE_MISMATCH);
				}
				PortRef first = senders.putIfAbsent(target.key(), targetRef);
				if (first != null) {
					error(target.describe() + " has two senders: it is already the target of a connector on line "
							+ NodeModelUtils.getNode(first).getStartLine(), targetRef, null,
							ArcIssueCodes.TWO_SENDERS);
				}
			}
		}
		warnUnconnected(c, senders.keySet());
	}

	private void warnUnconnected(ComponentType c, Set<String> connected) {
		for (ArcPort p : ArcModels.ports(c, Direction.OUT)) {
			if (p.getName() != null && !connected.contains(p.getName())) {
				warning("outgoing port '" + p.getName() + "' of '" + c.getName() + "' has no sender: no connector ends at it", p,
						A.getArcNamedElement_Name(), ArcIssueCodes.UNCONNECTED_PORT);
			}
		}
		for (Subcomponent sub : ArcModels.subcomponents(c)) {
			ComponentType type = ArcModels.type(sub);
			if (sub.getName() == null || type == null || type.eIsProxy()) {
				continue;
			}
			for (ArcPort p : ArcModels.ports(type, Direction.IN)) {
				if (p.getName() != null && !connected.contains(sub.getName() + "." + p.getName())) {
					warning("incoming port '" + p.getName() + "' of subcomponent '" + sub.getName() + "' has no sender: no connector ends at it",
							sub, A.getArcNamedElement_Name(), ArcIssueCodes.UNCONNECTED_PORT);
				}
			}
		}
	}

	@Check
	public void checkInstantiationCycle(Subcomponent sub) {
		ComponentType owner = ArcModels.component(sub);
		ComponentType type = ArcModels.type(sub);
		if (type == null || type.eIsProxy()) {
			return;
		}
		Set<ComponentType> seen = new HashSet<>();
		Deque<ComponentType> todo = new ArrayDeque<>();
		todo.push(type);
		while (!todo.isEmpty()) {
			ComponentType t = todo.pop();
			if (t == owner) {
				error("instantiation cycle: '" + owner.getName() + "' contains '" + sub.getName() + "' of type '" + type.getName()
						+ "', which " + (type == owner ? "is '" + owner.getName() + "' itself" : "contains '" + owner.getName() + "' again"),
						sub, A.getArcNamedElement_Name(), ArcIssueCodes.INSTANTIATION_CYCLE);
				return;
			}
			if (seen.add(t)) {
				for (Subcomponent s : ArcModels.subcomponents(t)) {
					ComponentType st = ArcModels.type(s);
					if (st != null && !st.eIsProxy()) {
						todo.push(st);
					}
				}
			}
		}
	}

	@Check
	public void checkArguments(Subcomponent sub) {
		ComponentType type = ArcModels.type(sub);
		if (type == null || type.eIsProxy()) {
			return;
		}
		int expected = type.getParameters().size();
		int required = (int) type.getParameters().stream().filter(p -> p.getDefaultValue() == null).count();
		int actual = sub.getArguments().size();
		if (actual < required || actual > expected) {
			error("subcomponent '" + sub.getName() + "' gets " + actual + " argument" + (actual == 1 ? "" : "s") + " but component '"
					+ type.getName() + "' has " + expected + " configuration parameter" + (expected == 1 ? "" : "s"), sub,
					A.getArcNamedElement_Name(), ArcIssueCodes.ARGUMENT_COUNT);
		}
	}

	@Check
	public void checkOneAutomaton(ComponentType c) {
		for (int i = 1; i < c.getAutomata().size(); i++) {
			error("component '" + c.getName() + "' has more than one automaton", c.getAutomata().get(i), null,
					ArcIssueCodes.MULTIPLE_AUTOMATA);
		}
	}

	@Check
	public void checkAutomaton(Automaton automaton) {
		Set<String> names = new HashSet<>();
		for (AutomatonState s : ArcModels.allStates(automaton)) {
			if (s.getName() != null && !names.add(s.getName())) {
				error("duplicate state '" + s.getName() + "'", s, A.getArcNamedElement_Name(), ArcIssueCodes.DUPLICATE_NAME);
			}
			if (!s.getStates().isEmpty()) {
				checkInitial(s.getStates(), s, "state '" + s.getName() + "' has substates but none is initial (declare one 'initial state S;')");
			}
		}
		if (checkInitial(automaton.getStates(), automaton, "the automaton has no initial state (declare one 'initial state S;')")) {
			warnUnreachable(automaton);
		}
		checkDeterminism(automaton);
	}

	/** One initial state among siblings; false if there is none. */
	private boolean checkInitial(List<AutomatonState> siblings, EObject owner, String noneMessage) {
		boolean initialSeen = false;
		for (AutomatonState s : siblings) {
			if (s.isInitial()) {
				if (initialSeen) {
					error("more than one initial state: '" + s.getName() + "' is initial too", s, A.getArcNamedElement_Name(),
							ArcIssueCodes.MULTIPLE_INITIAL_STATES);
				}
				initialSeen = true;
			}
		}
		if (!initialSeen) {
			error(noneMessage, owner, owner instanceof AutomatonState ? A.getArcNamedElement_Name() : null, ArcIssueCodes.NO_INITIAL_STATE);
		}
		return initialSeen;
	}

	private void warnUnreachable(Automaton automaton) {
		// entering a state enters its super states and its initial substates; a super state's transitions leave any of its substates
		Set<AutomatonState> reached = new HashSet<>();
		Deque<AutomatonState> todo = new ArrayDeque<>();
		todo.push(ArcModels.initialState(automaton));
		List<Transition> transitions = ArcModels.allTransitions(automaton);
		while (!todo.isEmpty()) {
			AutomatonState s = todo.pop();
			if (s != null && reached.add(s)) {
				todo.addAll(ArcModels.ancestry(s));
				AutomatonState initial = ArcModels.initialState(s.getStates());
				if (initial != null) {
					todo.push(initial);
				}
				for (Transition t : transitions) {
					if (t.getSource() == s && t.getTarget() != null && !t.getTarget().eIsProxy()) {
						todo.push(t.getTarget());
					}
				}
			}
		}
		for (AutomatonState s : ArcModels.allStates(automaton)) {
			if (!reached.contains(s)) {
				warning("state '" + s.getName() + "' is unreachable: no transitions lead to it from the initial state", s,
						A.getArcNamedElement_Name(), ArcIssueCodes.UNREACHABLE_STATE);
			}
		}
	}

	/** Two transitions of one state and trigger that can both fire: one without a guard, or the same guard twice. */
	private void checkDeterminism(Automaton automaton) {
		List<Transition> transitions = ArcModels.allTransitions(automaton);
		for (int i = 0; i < transitions.size(); i++) {
			Transition later = transitions.get(i);
			for (int j = 0; j < i; j++) {
				Transition earlier = transitions.get(j);
				if (earlier.getSource() != later.getSource() || earlier.getTrigger() != later.getTrigger() || earlier.getSource() == null) {
					continue;
				}
				boolean overlap = earlier.getGuard() == null || later.getGuard() == null || guardText(earlier).equals(guardText(later));
				if (overlap) {
					String on = later.getTrigger() == null ? "without a trigger" : "on '" + later.getTrigger().getName() + "'";
					error("nondeterministic: state '" + later.getSource().getName() + "' has two transitions " + on + " that can both fire (line "
							+ NodeModelUtils.getNode(earlier).getStartLine() + " and this one): give them guards that exclude each other", later,
							null, ArcIssueCodes.NONDETERMINISTIC_TRANSITIONS);
					break;
				}
			}
		}
	}

	private static String guardText(Transition t) {
		return NodeModelUtils.getTokenText(NodeModelUtils.getNode(t.getGuard()));
	}

	@Check
	public void checkAutomatonOnlyInAtomic(ComponentType c) {
		if (ArcModels.isComposed(c)) {
			for (Automaton a : c.getAutomata()) {
				error("component '" + c.getName() + "' has subcomponents, so its behaviour is theirs: it cannot also have an automaton", a,
						null, ArcIssueCodes.AUTOMATON_IN_COMPOSED);
			}
		}
	}

	@Check
	public void checkTransition(Transition t) {
		ArcPort trigger = t.getTrigger();
		if (trigger != null && !trigger.eIsProxy() && ArcModels.direction(trigger) != Direction.IN) {
			error("the trigger of a transition must be an incoming port; '" + trigger.getName() + "' is outgoing", t, A.getTransition_Trigger(),
					ArcIssueCodes.DIRECTION_MISMATCH);
		}
		if (t.getGuard() != null) {
			String type = ArcExpressionTypes.check(t.getGuard(), this::report);
			if (!ArcExpressionTypes.isBoolean(type)) {
				error("the guard must be boolean, not " + type, t.getGuard(), null, ArcIssueCodes.EXPRESSION_TYPE);
			}
		}
	}

	@Check
	public void checkExpressionStatement(ExpressionStatement es) {
		ArcExpressionTypes.check(es.getExpression(), this::report);
		boolean call = es.getExpression() instanceof MemberAccess m && m.isCall() || es.getExpression() instanceof NewInstance;
		if (!call) {
			error("only a method call can stand alone in an action; assign or send the value instead", es, null, ArcIssueCodes.EXPRESSION_TYPE);
		}
	}

	@Check
	public void checkIf(org.triad.dsl.arc.IfStatement i) {
		String type = ArcExpressionTypes.check(i.getCondition(), this::report);
		if (!ArcExpressionTypes.isBoolean(type)) {
			error("the if condition must be boolean, not " + type, i.getCondition(), null, ArcIssueCodes.EXPRESSION_TYPE);
		}
	}

	@Check
	public void checkSwitch(org.triad.dsl.arc.SwitchStatement sw) {
		ArcExpressionTypes.check(sw.getSubject(), this::report);
	}

	@Check
	public void checkLocalVariable(org.triad.dsl.arc.LocalVariable v) {
		if (v.getInitial() == null || v.getType() == null) {
			return;
		}
		String value = ArcExpressionTypes.check(v.getInitial(), this::report);
		if (!ArcExpressionTypes.isAssignable(value, v.getType().trim(), ArcModels.component(v))) {
			error("cannot initialise " + v.getType().trim() + " '" + v.getName() + "' with " + value, v.getInitial(), null,
					ArcIssueCodes.EXPRESSION_TYPE);
		}
	}

	@Check
	public void checkAssignment(Assignment a) {
		ComponentType c = ArcModels.component(a);
		String value = ArcExpressionTypes.check(a.getValue(), this::report);
		ArcNamedElement target = a.getTarget();
		if (target == null || target.eIsProxy()) {
			return;
		}
		String targetType;
		if (target instanceof ArcPort port) {
			if (ArcModels.direction(port) == Direction.IN) {
				error("cannot send on incoming port '" + port.getName() + "': an action sends on outgoing ports only", a, A.getAssignment_Target(),
						ArcIssueCodes.SEND_ON_INPUT);
				return;
			}
			targetType = ArcModels.typeName(port).trim();
		} else if (target instanceof ConfigParameter p) {
			error("configuration parameter '" + p.getName() + "' is fixed when the component is created and cannot be assigned; use a variable",
					a, A.getAssignment_Target(), ArcIssueCodes.NOT_ASSIGNABLE);
			return;
		} else if (target instanceof org.triad.dsl.arc.LocalVariable v) {
			targetType = v.getType().trim();
		} else {
			targetType = ((Variable) target).getType().trim();
		}
		if (!ArcExpressionTypes.isAssignable(value, targetType, c)) {
			error((target instanceof ArcPort ? "cannot send " : "cannot assign ") + value + " to " + targetType + " '" + target.getName() + "'",
					a.getValue(), null, ArcIssueCodes.EXPRESSION_TYPE);
		}
	}

	@Check
	public void checkVariable(Variable v) {
		if (v.getInitial() == null || v.getType() == null) {
			return;
		}
		String value = ArcExpressionTypes.check(v.getInitial(), this::report);
		if (!ArcExpressionTypes.isAssignable(value, v.getType().trim(), ArcModels.component(v))) {
			error("cannot initialise " + v.getType().trim() + " '" + v.getName() + "' with " + value, v.getInitial(), null,
					ArcIssueCodes.EXPRESSION_TYPE);
		}
	}

	private void report(String code, String message, EObject where) {
		error(message, where, null, code);
	}

	@Check
	public void checkTypeArgumentsAreReferenceTypes(Subcomponent sub) {
		for (int i = 0; i < ArcModels.typeArguments(sub).size(); i++) {
			String argument = ArcModels.typeArguments(sub).get(i).trim();
			if (ArcExpressionTypes.isPrimitive(argument)) {
				error("type argument " + argument + " of subcomponent '" + sub.getName() + "' must be a reference type (its box, e.g. "
						+ (argument.equals("int") ? "Integer" : argument.equals("char") ? "Character"
								: Character.toUpperCase(argument.charAt(0)) + argument.substring(1)) + ")",
						sub, A.getArcNamedElement_Name(), ArcIssueCodes.PRIMITIVE_TYPE_ARGUMENT);
			}
		}
	}

	@Check
	public void checkTypeArguments(Subcomponent sub) {
		ComponentType type = ArcModels.type(sub);
		if (type == null || type.eIsProxy()) {
			return;
		}
		int expected = type.getTypeParameters().size();
		int actual = ArcModels.typeArguments(sub).size();
		if (expected != actual) {
			error("subcomponent '" + sub.getName() + "' gives " + actual + " type argument" + (actual == 1 ? "" : "s") + " but component '"
					+ type.getName() + "' has " + expected + " type parameter" + (expected == 1 ? "" : "s")
					+ (expected == 0 ? "" : " (" + String.join(", ", ArcModels.typeParameterNames(type)) + ")"), sub,
					A.getArcNamedElement_Name(), ArcIssueCodes.TYPE_ARGUMENT_COUNT);
		}
	}

	private static final Set<String> TIMINGS = Set.of("sync", "timed", "untimed");

	@Check
	public void checkInheritance(ComponentType c) {
		ComponentType parent = ArcModels.parent(c);
		if (parent == null) {
			return;
		}
		Set<ComponentType> seen = new HashSet<>();
		for (ComponentType t = parent; t != null && !t.eIsProxy(); t = t.getParent()) {
			if (t == c) {
				error("inheritance cycle: component '" + c.getName() + "' extends '" + parent.getName() + "', which "
						+ (parent == c ? "is itself" : "extends '" + c.getName() + "' again"), c, A.getComponentType_Parent(),
						ArcIssueCodes.INHERITANCE_CYCLE);
				return;
			}
			if (!seen.add(t)) {
				return;
			}
		}
		int expected = parent.getParameters().size();
		int required = (int) parent.getParameters().stream().filter(p -> p.getDefaultValue() == null).count();
		int actual = c.getParentArguments().size();
		if (actual < required || actual > expected) {
			error("component '" + c.getName() + "' gives its parent '" + parent.getName() + "' " + actual + " argument" + (actual == 1 ? "" : "s")
					+ " but it has " + expected + " configuration parameter" + (expected == 1 ? "" : "s"), c, A.getComponentType_Parent(),
					ArcIssueCodes.ARGUMENT_COUNT);
		}
	}

	@Check
	public void checkPortStereotypes(org.triad.dsl.arc.PortDeclaration d) {
		if (d.getStereotype() == null) {
			return;
		}
		List<String> values = d.getStereotype().getValues();
		if (values.contains("delayed") && d.getDirection() == Direction.IN) {
			error("incoming ports cannot be <<delayed>>: only an outgoing port holds its messages back for a time slice", d, null,
					ArcIssueCodes.DELAYED_IN_PORT);
		}
		checkTimings(values, d);
	}

	@Check
	public void checkAutomatonStereotype(Automaton a) {
		if (a.getStereotype() != null) {
			checkTimings(a.getStereotype().getValues(), a);
		}
	}

	private void checkTimings(List<String> values, EObject where) {
		List<String> timings = values.stream().filter(TIMINGS::contains).distinct().toList();
		if (timings.size() > 1) {
			error("only one timing is allowed, not " + String.join(" and ", timings), where, null, ArcIssueCodes.MULTIPLE_TIMINGS);
		}
	}

	@Check
	public void checkOptionalParametersLast(ComponentType c) {
		boolean optional = false;
		for (ConfigParameter p : c.getParameters()) {
			if (p.getDefaultValue() != null) {
				optional = true;
			} else if (optional) {
				error("configuration parameter '" + p.getName() + "' has no default value but follows one that has: parameters with defaults come last",
						p, A.getArcNamedElement_Name(), ArcIssueCodes.OPTIONAL_PARAMETER_ORDER);
			}
		}
	}

	@Check
	public void checkTypeBounds(org.triad.dsl.arc.SubcomponentDeclaration d) {
		ComponentType type = d.getType();
		if (type == null || type.eIsProxy() || type.getTypeParameters().size() != d.getTypeArguments().size()) {
			return;
		}
		for (int i = 0; i < d.getTypeArguments().size(); i++) {
			String bound = type.getTypeParameters().get(i).getUpperBound();
			String argument = d.getTypeArguments().get(i).trim();
			if (bound != null && !ArcTypes.withinBound(argument, bound.trim())) {
				error("type argument " + argument + " is not within the bound of " + type.getName() + "'s type parameter "
						+ type.getTypeParameters().get(i).getName() + " extends " + bound.trim(), d, A.getSubcomponentDeclaration_TypeArguments(), i,
						ArcIssueCodes.TYPE_BOUND);
			}
		}
	}

	/** Type.MEMBER in an expression: Type must be a data type of a class diagram, a type parameter or a java.lang class. */
	@Check
	public void checkTypeQualifier(org.triad.dsl.arc.NameRef r) {
		if (!ArcModels.isTypeQualifier(r)) {
			return;
		}
		String name = ArcModels.qualifierText(r);
		if (ArcModels.typeParameterNames(ArcModels.component(r)).contains(name) || ArcTypes.isJavaLangClass(name) || isDataType(r, name)) {
			return;
		}
		error("unknown name '" + name + "': not a variable, configuration parameter or port of component '" + ArcModels.component(r).getName()
				+ "', nor a data type of a class diagram or a java.lang class", r, null, ArcIssueCodes.UNKNOWN_NAME);
	}

	private boolean isDataType(EObject context, String name) {
		String simple = name.substring(name.lastIndexOf('.') + 1);
		IResourceDescriptions index = indexProvider.getResourceDescriptions(context.eResource());
		for (IEObjectDescription d : index.getExportedObjectsByType(org.triad.dsl.triad.TriadPackage.Literals.DOMAIN_TYPE)) {
			if (d.getName().getLastSegment().equals(simple)) {
				return true;
			}
		}
		return false;
	}

	/**
	 * Subcomponents that run in time slices and send to each other in a loop need a delayed port on it
	 * (MontiArc's strong causality). Event-driven components (RefArc's) handle messages as they come and
	 * may form loops.
	 */
	@Check
	public void checkFeedbackLoops(ComponentType c) {
		List<Subcomponent> subs = ArcModels.subcomponents(c).stream().filter(s -> ArcModels.isTimed(ArcModels.type(s))).toList();
		Map<Subcomponent, Set<Subcomponent>> next = new HashMap<>();
		for (Connector con : c.getConnectors()) {
			PortRef src = con.getSource();
			if (src == null || src.getSubcomponent() == null || src.getSubcomponent().eIsProxy() || src.getPort() == null || src.getPort().eIsProxy()) {
				continue;
			}
			if (delayedOutput(ArcModels.type(src.getSubcomponent()), src.getPort(), new HashSet<>())) {
				continue;
			}
			for (PortRef t : con.getTargets()) {
				if (t.getSubcomponent() != null && !t.getSubcomponent().eIsProxy() && subs.contains(t.getSubcomponent())) {
					next.computeIfAbsent(src.getSubcomponent(), k -> new java.util.LinkedHashSet<>()).add(t.getSubcomponent());
				}
			}
		}
		Set<Subcomponent> reported = new HashSet<>();
		for (Subcomponent start : subs) {
			List<Subcomponent> loop = loopFrom(start, next);
			if (loop != null && !reported.contains(start)) {
				reported.addAll(loop);
				error("feedback loop without a delayed port: " + String.join(" -> ", loop.stream().map(Subcomponent::getName).toList())
						+ "; within one time slice each would wait for the other (make an outgoing port on the loop <<delayed>>, or put a Delay in it)",
						start, A.getArcNamedElement_Name(), ArcIssueCodes.FEEDBACK_WITHOUT_DELAY);
			}
		}
	}

	private static List<Subcomponent> loopFrom(Subcomponent start, Map<Subcomponent, Set<Subcomponent>> next) {
		Deque<List<Subcomponent>> todo = new ArrayDeque<>();
		todo.add(List.of(start));
		Set<Subcomponent> seen = new HashSet<>();
		while (!todo.isEmpty()) {
			List<Subcomponent> path = todo.poll();
			for (Subcomponent n : next.getOrDefault(path.get(path.size() - 1), Set.of())) {
				List<Subcomponent> longer = new ArrayList<>(path);
				longer.add(n);
				if (n == start) {
					return longer;
				}
				if (seen.add(n)) {
					todo.add(longer);
				}
			}
		}
		return null;
	}

	/** Whether messages of an outgoing port come a time slice late: it is <<delayed>>, or inside a composed component its sender's is. */
	private static boolean delayedOutput(ComponentType type, ArcPort port, Set<ArcPort> seen) {
		if (ArcModels.isDelayed(port)) {
			return true;
		}
		if (type == null || type.eIsProxy() || !ArcModels.isComposed(type) || !seen.add(port)) {
			return false;
		}
		for (Connector con : type.getConnectors()) {
			for (PortRef t : con.getTargets()) {
				if (t.getSubcomponent() == null && t.getPort() == port) {
					PortRef src = con.getSource();
					return src != null && src.getSubcomponent() != null && !src.getSubcomponent().eIsProxy() && src.getPort() != null
							&& delayedOutput(ArcModels.type(src.getSubcomponent()), src.getPort(), seen);
				}
			}
		}
		return false;
	}

	private static String kind(EObject e) {
		if (e instanceof ArcPort) {
			return "port";
		}
		if (e instanceof Subcomponent) {
			return "subcomponent";
		}
		if (e instanceof Variable) {
			return "variable";
		}
		return "configuration parameter";
	}

	/** A resolved end of a connector. */
	private record Endpoint(String key, String label, boolean own, Direction direction, String type) {
		static Endpoint of(PortRef ref) {
			if (ref == null) {
				return null;
			}
			if (ref.isFaults()) {
				return new Endpoint(ArcModels.FAULTS_PORT, ArcModels.FAULTS_PORT, true, Direction.IN, ArcModels.FAULT_TYPE);
			}
			ArcPort port = ref.getPort();
			if (port == null || port.eIsProxy()) {
				return null;
			}
			Subcomponent sub = ref.getSubcomponent();
			if (sub != null && sub.eIsProxy()) {
				return null;
			}
			String declared = substitute(ArcModels.typeName(port), sub);
			String type = declared == null ? null : ArcTypes.resolve(declared, sub == null ? ArcModels.imports(port) : ArcModels.imports(sub));
			String label = sub == null ? port.getName() : sub.getName() + "." + port.getName();
			return new Endpoint(label, label, sub == null, ArcModels.direction(port), type);
		}

		/** A port type of a generic subcomponent's type with its type parameters replaced by the subcomponent's type arguments. */
		private static String substitute(String portType, Subcomponent sub) {
			if (sub == null || ArcModels.type(sub) == null || ArcModels.type(sub).eIsProxy()) {
				return portType;
			}
			List<String> parameters = ArcModels.typeParameterNames(ArcModels.type(sub));
			int i = parameters.indexOf(ArcTypes.erasure(portType));
			if (i < 0) {
				return portType;
			}
			// with the wrong number of type arguments (reported on the subcomponent) the type is unknown
			return parameters.size() == ArcModels.typeArguments(sub).size() ? ArcModels.typeArguments(sub).get(i).trim() : null;
		}

		boolean canSend() {
			return own == (direction == Direction.IN);
		}

		boolean canReceive() {
			return own == (direction == Direction.OUT);
		}

		String describe() {
			return (direction == Direction.IN ? "incoming" : "outgoing") + " port '" + label + "'";
		}
	}
}
