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
		members.addAll(c.getSubcomponents());
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
		for (Subcomponent sub : c.getSubcomponents()) {
			ComponentType type = sub.getType();
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
		ComponentType owner = (ComponentType) sub.eContainer();
		ComponentType type = sub.getType();
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
						sub, A.getSubcomponent_Type(), ArcIssueCodes.INSTANTIATION_CYCLE);
				return;
			}
			if (seen.add(t)) {
				for (Subcomponent s : t.getSubcomponents()) {
					ComponentType st = s.getType();
					if (st != null && !st.eIsProxy()) {
						todo.push(st);
					}
				}
			}
		}
	}

	@Check
	public void checkArguments(Subcomponent sub) {
		ComponentType type = sub.getType();
		if (type == null || type.eIsProxy()) {
			return;
		}
		int expected = type.getParameters().size();
		int actual = sub.getArguments().size();
		if (expected != actual) {
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
		boolean initialSeen = false;
		for (AutomatonState s : automaton.getStates()) {
			if (s.getName() != null && !names.add(s.getName())) {
				error("duplicate state '" + s.getName() + "'", s, A.getArcNamedElement_Name(), ArcIssueCodes.DUPLICATE_NAME);
			}
			if (s.isInitial()) {
				if (initialSeen) {
					error("more than one initial state: '" + s.getName() + "' is initial too", s, A.getArcNamedElement_Name(),
							ArcIssueCodes.MULTIPLE_INITIAL_STATES);
				}
				initialSeen = true;
			}
		}
		if (!initialSeen) {
			error("the automaton has no initial state (declare one 'initial state S;')", automaton, null, ArcIssueCodes.NO_INITIAL_STATE);
		} else {
			warnUnreachable(automaton);
		}
		checkDeterminism(automaton);
	}

	private void warnUnreachable(Automaton automaton) {
		Set<AutomatonState> reached = new HashSet<>();
		Deque<AutomatonState> todo = new ArrayDeque<>();
		todo.push(ArcModels.initialState(automaton));
		while (!todo.isEmpty()) {
			AutomatonState s = todo.pop();
			if (reached.add(s)) {
				for (Transition t : automaton.getTransitions()) {
					if (t.getSource() == s && t.getTarget() != null && !t.getTarget().eIsProxy()) {
						todo.push(t.getTarget());
					}
				}
			}
		}
		for (AutomatonState s : automaton.getStates()) {
			if (!reached.contains(s)) {
				warning("state '" + s.getName() + "' is unreachable: no transitions lead to it from the initial state", s,
						A.getArcNamedElement_Name(), ArcIssueCodes.UNREACHABLE_STATE);
			}
		}
	}

	/** Two transitions of one state and trigger that can both fire: one without a guard, or the same guard twice. */
	private void checkDeterminism(Automaton automaton) {
		List<Transition> transitions = automaton.getTransitions();
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
		ComponentType c = ArcModels.component(t);
		for (Statement st : t.getActions()) {
			if (st instanceof Assignment a) {
				checkAssignment(a, c);
			} else if (st instanceof ExpressionStatement es) {
				ArcExpressionTypes.check(es.getExpression(), this::report);
				boolean call = es.getExpression() instanceof MemberAccess m && m.isCall() || es.getExpression() instanceof NewInstance;
				if (!call) {
					error("only a method call can stand alone in an action; assign or send the value instead", es, null,
							ArcIssueCodes.EXPRESSION_TYPE);
				}
			}
		}
	}

	private void checkAssignment(Assignment a, ComponentType c) {
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
		for (int i = 0; i < sub.getTypeArguments().size(); i++) {
			String argument = sub.getTypeArguments().get(i).trim();
			if (ArcExpressionTypes.isPrimitive(argument)) {
				error("type argument " + argument + " of subcomponent '" + sub.getName() + "' must be a reference type (its box, e.g. "
						+ (argument.equals("int") ? "Integer" : argument.equals("char") ? "Character"
								: Character.toUpperCase(argument.charAt(0)) + argument.substring(1)) + ")",
						sub, A.getSubcomponent_TypeArguments(), i, ArcIssueCodes.PRIMITIVE_TYPE_ARGUMENT);
			}
		}
	}

	@Check
	public void checkTypeArguments(Subcomponent sub) {
		ComponentType type = sub.getType();
		if (type == null || type.eIsProxy()) {
			return;
		}
		int expected = type.getTypeParameters().size();
		int actual = sub.getTypeArguments().size();
		if (expected != actual) {
			error("subcomponent '" + sub.getName() + "' gives " + actual + " type argument" + (actual == 1 ? "" : "s") + " but component '"
					+ type.getName() + "' has " + expected + " type parameter" + (expected == 1 ? "" : "s")
					+ (expected == 0 ? "" : " (" + String.join(", ", ArcModels.typeParameterNames(type)) + ")"), sub,
					A.getSubcomponent_Type(), ArcIssueCodes.TYPE_ARGUMENT_COUNT);
		}
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
			if (sub == null || sub.getType() == null || sub.getType().eIsProxy()) {
				return portType;
			}
			List<String> parameters = ArcModels.typeParameterNames(sub.getType());
			int i = parameters.indexOf(ArcTypes.erasure(portType));
			if (i < 0) {
				return portType;
			}
			// with the wrong number of type arguments (reported on the subcomponent) the type is unknown
			return parameters.size() == sub.getTypeArguments().size() ? sub.getTypeArguments().get(i).trim() : null;
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
