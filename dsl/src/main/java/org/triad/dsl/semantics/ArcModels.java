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

/** Derived facts of architecture models that the metamodel keeps implicit (a port's direction is its declaration's). */
public final class ArcModels {
	/** The runtime-fed in port of every composed component ({@code ComposedComponent.FAULTS}). */
	public static final String FAULTS_PORT = "faults";
	/** Type of the {@code faults} port. */
	public static final String FAULT_TYPE = "org.triad.runtime.component.ComponentFault";

	private ArcModels() {
	}

	public static List<ArcPort> ports(ComponentType c) {
		List<ArcPort> ports = new ArrayList<>();
		for (PortDeclaration d : c.getPortDeclarations()) {
			ports.addAll(d.getPorts());
		}
		return ports;
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
		return !c.getSubcomponents().isEmpty();
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
		return a.getStates().stream().filter(AutomatonState::isInitial).findFirst().orElse(null);
	}

	/** The names a guard or action can use: variables, configuration parameters and ports of the component. */
	public static List<ArcNamedElement> members(ComponentType c) {
		List<ArcNamedElement> members = new ArrayList<>();
		members.addAll(c.getVariables());
		members.addAll(c.getParameters());
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
