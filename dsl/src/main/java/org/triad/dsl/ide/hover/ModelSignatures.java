package org.triad.dsl.ide.hover;

import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.ConfigParameter;
import org.triad.dsl.arc.PortDeclaration;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainTypeRef;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.GoalReference;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Parameterized;
import org.triad.dsl.triad.PrimitiveTypeRef;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.TypeRef;

/**
 * An element's declaration written in its model's own syntax (what a model author would write),
 * for hovers, signature help and symbol details. Bodies that are model text (conditions,
 * pre/postconditions) are taken from the source so they read exactly as written.
 */
public final class ModelSignatures {
	private ModelSignatures() {
	}

	/** The element's declaration, possibly several lines; null for elements that declare nothing. */
	public static String of(EObject e) {
		if (e instanceof ClassDiagram cd) {
			return "classdiagram " + cd.getName();
		}
		if (e instanceof DomainClass c) {
			StringBuilder b = new StringBuilder();
			if (c.isAbstract()) {
				b.append("abstract ");
			}
			b.append("class ").append(c.getName());
			if (c.getSuperType() != null && !c.getSuperType().eIsProxy()) {
				b.append(" extends ").append(c.getSuperType().getName());
			}
			if (c.getAttributes().isEmpty()) {
				return b.append(';').toString();
			}
			b.append(" {");
			for (Attribute a : c.getAttributes()) {
				b.append("\n  ").append(type(a.getType())).append(' ').append(a.getName()).append(';');
			}
			return b.append("\n}").toString();
		}
		if (e instanceof Enumeration en) {
			return "enum " + en.getName() + " { " + en.getLiterals().stream().map(EnumLiteral::getName).collect(Collectors.joining(", ")) + " }";
		}
		if (e instanceof EnumLiteral l) {
			Enumeration en = EcoreUtil2.getContainerOfType(l, Enumeration.class);
			return (en == null ? "" : en.getName() + ".") + l.getName();
		}
		if (e instanceof Attribute a) {
			return type(a.getType()) + " " + owner(a) + a.getName() + ";";
		}
		if (e instanceof Actor actor) {
			StringBuilder b = new StringBuilder(actor.getKind().getLiteral()).append(' ').append(actor.getName()).append(" {");
			for (Property p : actor.getProperties()) {
				b.append("\n  ").append(propertyHead(p)).append(';');
			}
			for (Action a : actor.getActions()) {
				b.append("\n  action ").append(head(a)).append(';');
			}
			return b.append("\n}").toString();
		}
		if (e instanceof Property p) {
			Actor actor = EcoreUtil2.getContainerOfType(p, Actor.class);
			return (actor == null ? "" : "// " + actor.getKind().getLiteral() + " " + actor.getName() + "\n") + propertyHead(p) + ";";
		}
		if (e instanceof Action a) {
			Actor actor = EcoreUtil2.getContainerOfType(a, Actor.class);
			StringBuilder b = new StringBuilder();
			if (actor != null) {
				b.append("// ").append(actor.getKind().getLiteral()).append(' ').append(actor.getName()).append('\n');
			}
			b.append("action ").append(head(a)).append(" {");
			if (a.getPre() != null) {
				b.append("\n  pre: ").append(text(a.getPre())).append(';');
			}
			if (a.getPost() != null) {
				b.append("\n  post: ").append(text(a.getPost())).append(';');
			}
			return b.append("\n}").toString();
		}
		if (e instanceof Goal g) {
			return "goal " + head(g) + " {\n  " + text(g.getCondition()) + "\n}";
		}
		if (e instanceof Task t) {
			StringBuilder b = new StringBuilder("task ").append(head(t)).append(" {");
			for (GoalReference step : t.getSteps()) {
				b.append("\n  ").append(text(step));
			}
			return b.append("\n}").toString();
		}
		if (e instanceof Parameter p) {
			Parameterized owner = EcoreUtil2.getContainerOfType(p.eContainer(), Parameterized.class);
			String of = owner == null ? "" : "// parameter of " + kind(owner) + " " + owner.getName() + "\n";
			return of + type(p.getType()) + " " + p.getName();
		}
		if (e instanceof SituationObject o) {
			ObjectDeclaration d = EcoreUtil2.getContainerOfType(o, ObjectDeclaration.class);
			Situation s = EcoreUtil2.getContainerOfType(o, Situation.class);
			String typeName = d == null || d.getType() == null || d.getType().eIsProxy() ? "?" : d.getType().getName();
			String of = s == null ? "" : "// object of state " + s.getName() + "\n";
			return of + typeName + " " + (o.getAssignments().isEmpty() ? o.getName() : text(o)) + ";";
		}
		if (e instanceof Situation s) {
			return "state " + s.getName();
		}
		if (e instanceof ComponentType c) {
			StringBuilder b = new StringBuilder("component ").append(c.getName());
			if (!c.getParameters().isEmpty()) {
				b.append('(').append(c.getParameters().stream().map(p -> p.getType() + " " + p.getName()).collect(Collectors.joining(", "))).append(')');
			}
			b.append(" {");
			for (PortDeclaration d : c.getPortDeclarations()) {
				b.append("\n  ").append(text(d));
			}
			return b.append("\n}").toString();
		}
		if (e instanceof ArcPort port && port.eContainer() instanceof PortDeclaration d) {
			return "port " + d.getDirection().getLiteral() + " " + d.getType() + " " + port.getName() + ";";
		}
		if (e instanceof Subcomponent s) {
			return text(s);
		}
		if (e instanceof ConfigParameter p) {
			return p.getType() + " " + p.getName();
		}
		if (e instanceof AutomatonState s) {
			return (s.isInitial() ? "initial " : "") + "state " + s.getName() + ";";
		}
		return null;
	}

	/** {@code name(Type a, Type b)} of a property, action, goal or task. */
	public static String head(Parameterized p) {
		return p.getName() + "(" + parameters(p.getParameters()) + ")";
	}

	/** The parameters as declared: {@code Type a, Type b}. */
	public static String parameters(List<Parameter> parameters) {
		return parameters.stream().map(ModelSignatures::parameter).collect(Collectors.joining(", "));
	}

	public static String parameter(Parameter p) {
		return type(p.getType()) + " " + p.getName();
	}

	public static String propertyHead(Property p) {
		return "property " + type(p.getType()) + " " + head(p);
	}

	/** The type as written in models: a primitive's keyword or a class's or enumeration's name. */
	public static String type(TypeRef ref) {
		if (ref instanceof PrimitiveTypeRef p) {
			return p.getKind().getLiteral();
		}
		if (ref instanceof DomainTypeRef d && d.getType() != null) {
			if (!d.getType().eIsProxy()) {
				return d.getType().getName();
			}
			List<org.eclipse.xtext.nodemodel.INode> nodes = NodeModelUtils.findNodesForFeature(d, org.triad.dsl.triad.TriadPackage.Literals.DOMAIN_TYPE_REF__TYPE);
			return nodes.isEmpty() ? "?" : NodeModelUtils.getTokenText(nodes.get(0));
		}
		return "?";
	}

	/** What kind of element declares parameters, as the model's keyword. */
	public static String kind(Parameterized p) {
		if (p instanceof Property) {
			return "property";
		}
		if (p instanceof Action) {
			return "action";
		}
		if (p instanceof Goal) {
			return "goal";
		}
		return p instanceof Task ? "task" : "element";
	}

	private static String owner(Attribute a) {
		DomainClass c = EcoreUtil2.getContainerOfType(a, DomainClass.class);
		return c == null ? "" : c.getName() + ".";
	}

	/** The element's source text with its whitespace and comments normalised to single spaces. */
	public static String text(EObject e) {
		if (e == null) {
			return "";
		}
		ICompositeNode node = NodeModelUtils.findActualNodeFor(e);
		return node == null ? "" : NodeModelUtils.getTokenText(node);
	}

	/** Convenience for expressions. */
	public static String text(Expression e) {
		return text((EObject) e);
	}
}
