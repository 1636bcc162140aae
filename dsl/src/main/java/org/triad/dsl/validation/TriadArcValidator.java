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
				if (source != null && !ArcTypes.isAssignable(source.type(), target.type())) {
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
		}
	}

	private static String kind(EObject e) {
		if (e instanceof ArcPort) {
			return "port";
		}
		if (e instanceof Subcomponent) {
			return "subcomponent";
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
			String type = ArcTypes.resolve(ArcModels.typeName(port), ArcModels.imports(port));
			String label = sub == null ? port.getName() : sub.getName() + "." + port.getName();
			return new Endpoint(label, label, sub == null, ArcModels.direction(port), type);
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
