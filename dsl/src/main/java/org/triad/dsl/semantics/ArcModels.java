package org.triad.dsl.semantics;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.triad.dsl.arc.ArcImport;
import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.TypeParameter;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.arc.PortDeclaration;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.arc.SubcomponentDeclaration;
import org.triad.dsl.arc.Transition;

/** Derived facts of architecture models that the metamodel keeps implicit (a port's direction is its declaration's). */
public final class ArcModels {
	/** The runtime-fed in port of every composed component ({@code ComposedComponent.FAULTS}). */
	public static final String FAULTS_PORT = "faults";
	/** Type of the {@code faults} port. */
	public static final String FAULT_TYPE = "org.triad.runtime.component.ComponentFault";

	private ArcModels() {
	}

	/** Every port of the component: those it inherits from its parent components first, then its own. */
	public static List<ArcPort> ports(ComponentType c) {
		List<ArcPort> ports = new ArrayList<>();
		for (ComponentType t : lineage(c)) {
			ports.addAll(ownPorts(t));
		}
		return ports;
	}

	/** The ports the component declares itself (not inherited). */
	public static List<ArcPort> ownPorts(ComponentType c) {
		List<ArcPort> ports = new ArrayList<>();
		for (PortDeclaration d : c.getPortDeclarations()) {
			ports.addAll(d.getPorts());
		}
		return ports;
	}

	/** The component and its ancestors ({@code extends}), the root ancestor first; an inheritance cycle stops where it closes. */
	public static List<ComponentType> lineage(ComponentType c) {
		List<ComponentType> chain = new ArrayList<>();
		for (ComponentType t = c; t != null && !t.eIsProxy() && !chain.contains(t); t = t.getParent()) {
			chain.add(0, t);
		}
		return chain;
	}

	/** The component's parent component ({@code extends}), or null. */
	public static ComponentType parent(ComponentType c) {
		ComponentType p = c.getParent();
		return p == null || p.eIsProxy() ? null : p;
	}

	public static List<Subcomponent> subcomponents(ComponentType c) {
		List<Subcomponent> subs = new ArrayList<>();
		for (SubcomponentDeclaration d : c.getSubcomponentDeclarations()) {
			subs.addAll(d.getInstances());
		}
		return subs;
	}

	/** The component type of a subcomponent (its declaration's; {@code Nor a, b;} declares two). */
	public static ComponentType type(Subcomponent s) {
		return s.eContainer() instanceof SubcomponentDeclaration d ? d.getType() : null;
	}

	public static List<String> typeArguments(Subcomponent s) {
		return s.eContainer() instanceof SubcomponentDeclaration d ? d.getTypeArguments() : List.of();
	}

	/** Whether the port's declaration carries the stereotype (e.g. {@code <<delayed>>}). */
	public static boolean hasStereotype(ArcPort p, String value) {
		return p.eContainer() instanceof PortDeclaration d && d.getStereotype() != null && d.getStereotype().getValues().contains(value);
	}

	/** A delayed port's message reaches its receivers one time slice later (MontiArc's {@code <<delayed>>}): it breaks feedback loops. */
	public static boolean isDelayed(ArcPort p) {
		return hasStereotype(p, "delayed");
	}

	public static boolean hasStereotype(Automaton a, String value) {
		return a.getStereotype() != null && a.getStereotype().getValues().contains(value);
	}

	/**
	 * Whether the component runs in time slices (MontiArc's timed and synchronous semantics): a
	 * stereotype on a port or automaton, a compute or init block, or, for a composed component, a
	 * subcomponent that does. Such components run on a {@code TimeSlices} clock; the others are
	 * event-driven (a handler per message).
	 */
	public static boolean isTimed(ComponentType c) {
		return isTimed(c, new java.util.HashSet<>());
	}

	private static boolean isTimed(ComponentType c, java.util.Set<ComponentType> seen) {
		if (c == null || c.eIsProxy() || !seen.add(c)) {
			return false;
		}
		for (ComponentType t : lineage(c)) {
			if (!t.getComputeActions().isEmpty() || !t.getInitActions().isEmpty()) {
				return true;
			}
			for (PortDeclaration d : t.getPortDeclarations()) {
				if (d.getStereotype() != null) {
					return true;
				}
			}
			for (Automaton a : t.getAutomata()) {
				if (a.getStereotype() != null) {
					return true;
				}
			}
			for (Subcomponent s : subcomponents(t)) {
				if (isTimed(type(s), seen)) {
					return true;
				}
			}
		}
		return false;
	}

	/**
	 * Whether the element is a name that qualifies a member ({@code MotorCmd.STOP}, {@code Math.abs(x)}) and names no
	 * variable, parameter or port: a Java or class-diagram type then.
	 */
	public static boolean isTypeQualifier(EObject e) {
		return isQualifierPosition(e) && (((org.triad.dsl.arc.NameRef) e).getTarget() == null || ((org.triad.dsl.arc.NameRef) e).getTarget().eIsProxy());
	}

	/** Whether the element is a name in front of {@code .member} (without resolving it: linking asks this while resolving). */
	public static boolean isQualifierPosition(EObject e) {
		return e instanceof org.triad.dsl.arc.NameRef r && r.eContainer() instanceof org.triad.dsl.arc.MemberAccess m && m.getReceiver() == r;
	}

	/** The text of a type qualifier as written. */
	public static String qualifierText(org.triad.dsl.arc.NameRef r) {
		return NodeModelUtils.findNodesForFeature(r, org.triad.dsl.arc.ArcPackage.Literals.NAME_REF__TARGET).stream()
				.map(NodeModelUtils::getTokenText).findFirst().orElse("").trim();
	}

	/** Every state of the automaton, nested ones after their parent, in model order. */
	public static List<AutomatonState> allStates(Automaton a) {
		List<AutomatonState> all = new ArrayList<>();
		addStates(a.getStates(), all);
		return all;
	}

	private static void addStates(List<AutomatonState> states, List<AutomatonState> all) {
		for (AutomatonState s : states) {
			all.add(s);
			addStates(s.getStates(), all);
		}
	}

	/** The states with no substates: where a hierarchical automaton actually is. */
	public static List<AutomatonState> leafStates(Automaton a) {
		return allStates(a).stream().filter(s -> s.getStates().isEmpty()).toList();
	}

	/** Every transition of the automaton, wherever it is written (inside states too), in model order. */
	public static List<Transition> allTransitions(Automaton a) {
		List<Transition> all = new ArrayList<>(a.getTransitions());
		for (AutomatonState s : allStates(a)) {
			all.addAll(s.getTransitions());
		}
		return all;
	}

	/** The state a substate is nested in, or null at the top. */
	public static AutomatonState superState(AutomatonState s) {
		return s.eContainer() instanceof AutomatonState p ? p : null;
	}

	/** The state and its super states, innermost first. */
	public static List<AutomatonState> ancestry(AutomatonState s) {
		List<AutomatonState> chain = new ArrayList<>();
		for (AutomatonState t = s; t != null; t = superState(t)) {
			chain.add(t);
		}
		return chain;
	}

	/** The initial state among siblings (the automaton's top states or a state's substates), or null. */
	public static AutomatonState initialState(List<AutomatonState> siblings) {
		return siblings.stream().filter(AutomatonState::isInitial).findFirst().orElse(null);
	}

	public static List<ArcPort> ports(ComponentType c, Direction direction) {
		return ports(c).stream().filter(p -> direction(p) == direction).toList();
	}

	public static Direction direction(ArcPort p) {
		return ((PortDeclaration) p.eContainer()).getDirection();
	}

	/** The port's type as written in the model (a Java type name, possibly simple). */
	public static String typeName(ArcPort p) {
		return ((PortDeclaration) p.eContainer()).getType();
	}

	/** A composed component has subcomponents; an atomic one has none and its behavior is hand-written or an automaton. */
	public static boolean isComposed(ComponentType c) {
		return !subcomponents(c).isEmpty();
	}

	public static ArcModel model(EObject e) {
		return EcoreUtil2.getContainerOfType(e, ArcModel.class);
	}

	/** The package of the file the element is in; "" for none. */
	public static String packageName(EObject e) {
		ArcModel m = model(e);
		return m == null || m.getName() == null ? "" : m.getName();
	}

	public static String qualifiedName(ComponentType c) {
		String pkg = packageName(c);
		return pkg.isEmpty() ? c.getName() : pkg + "." + c.getName();
	}

	/**
	 * The text of the block comments right before an element (its documentation), without comment
	 * markers and leading asterisks; "" if there is none.
	 */
	public static String documentation(EObject e) {
		ICompositeNode node = NodeModelUtils.getNode(e);
		if (node == null) {
			return "";
		}
		StringBuilder text = new StringBuilder();
		for (ILeafNode leaf : node.getLeafNodes()) {
			if (!leaf.isHidden()) {
				break;
			}
			String t = leaf.getText();
			if (t.startsWith("/*")) {
				String body = t.substring(t.startsWith("/**") ? 3 : 2, t.length() - 2);
				for (String line : body.split("\\R")) {
					String l = line.strip();
					l = l.startsWith("*") ? l.substring(1).strip() : l;
					if (!l.isEmpty() || text.length() > 0) {
						text.append(l).append('\n');
					}
				}
			}
		}
		return text.toString().strip();
	}

	public static ComponentType component(EObject e) {
		return EcoreUtil2.getContainerOfType(e, ComponentType.class);
	}

	/** The component's automaton, or null: at most one is valid. */
	public static Automaton automaton(ComponentType c) {
		return c.getAutomata().isEmpty() ? null : c.getAutomata().get(0);
	}

	public static AutomatonState initialState(Automaton a) {
		return initialState(a.getStates());
	}

	/** The names a guard or action can use: variables, configuration parameters and ports of the component. */
	public static List<ArcNamedElement> members(ComponentType c) {
		List<ArcNamedElement> members = new ArrayList<>();
		for (ComponentType t : lineage(c)) {
			members.addAll(t.getVariables());
			members.addAll(t.getParameters());
		}
		members.addAll(ports(c));
		return members;
	}

	public static List<String> typeParameterNames(ComponentType c) {
		return c.getTypeParameters().stream().map(TypeParameter::getName).toList();
	}

	public static List<String> imports(EObject e) {
		ArcModel m = model(e);
		return m == null ? List.of() : m.getImports().stream().map(ArcImport::getImportedNamespace).filter(i -> i != null).toList();
	}
}
