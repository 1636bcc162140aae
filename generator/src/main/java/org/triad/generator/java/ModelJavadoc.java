package org.triad.generator.java;

import java.util.List;
import java.util.function.Function;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ActorKind;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * The javadoc of generated interface methods, written from the model: what an implementation must do or
 * return, in the model's own words (its conditions, its types), so that the robotics expert need not read
 * the models or the runtime to implement {@code IRobot} and {@code IWorld}.
 */
public final class ModelJavadoc {
	private ModelJavadoc() {
	}

	/** An action: what to do, when it is called and what must hold after a successful return. */
	public static String action(Actor actor, Action a) {
		StringBuilder b = new StringBuilder("/**\n");
		b.append(" * Action {@code ").append(signature(a.getName(), a.getParameters())).append("} of ").append(kind(actor)).append(" {@code ")
				.append(actor.getName()).append("}: carry it out on the ").append(isRobot(actor) ? "platform" : "environment")
				.append(" and return when it has ended.\n");
		if (a.getPre() != null) {
			b.append(" * RefArc calls it only when its precondition holds: {@code ").append(javadocText(a.getPre())).append("}.\n");
		}
		if (a.getPost() != null) {
			b.append(" * Return {@code true} when it succeeded, so that afterwards {@code ").append(javadocText(a.getPost()))
					.append("} holds as the properties report it;\n");
		} else {
			b.append(" * Return {@code true} when it succeeded;\n");
		}
		b.append(" * {@code false} when it failed (RefArc then observes the state again and re-plans). Do not throw for a failure.\n");
		return b.append(" */").toString();
	}

	/** A property: which value it reports and for which arguments it is asked. */
	public static String property(Actor actor, Property p, String worldInterface) {
		StringBuilder b = new StringBuilder("/**\n");
		String call = signature(p.getName(), p.getParameters());
		boolean isBoolean = TriadTypeSystem.typeOf(p.getType()).isBoolean();
		if (isBoolean) {
			b.append(" * Whether {@code ").append(call).append("} holds now (Boolean property of ").append(kind(actor)).append(" {@code ")
					.append(actor.getName()).append("}), as observed on the ").append(isRobot(actor) ? "platform" : "environment").append(".\n");
		} else {
			b.append(" * The current value of {@code ").append(call).append("} (property of ").append(kind(actor)).append(" {@code ")
					.append(actor.getName()).append("}, of type {@code ").append(TriadTypeSystem.typeOf(p.getType()).display())
					.append("}), as observed on the ").append(isRobot(actor) ? "platform" : "environment").append(";\n");
			b.append(" * an object must be one that {@code ").append(worldInterface).append("} lists; {@code null} when it has no value.\n");
		}
		if (!p.getParameters().isEmpty()) {
			b.append(" * RefArc observes the state by calling it for every combination of arguments of the right types among the objects\n");
			b.append(" * {@code ").append(worldInterface).append("} lists, so answer quickly and without side effects.\n");
		} else {
			b.append(" * Called whenever RefArc observes the state: answer quickly and without side effects.\n");
		}
		return b.append(" */").toString();
	}

	/** A world's objects method: all objects of the class known now, and how subclasses' objects count. */
	public static String objects(DomainClass c, List<DomainClass> classes, Function<DomainClass, String> objectsMethod) {
		StringBuilder b = new StringBuilder("/**\n");
		b.append(" * All objects of type {@code ").append(c.getName()).append("} known to the world now, each an instance of the generated class\n");
		b.append(" * with its model name ({@code new ").append(c.getName()).append("(\"storage\")}; the name is the object's identity in\n");
		b.append(" * situations and plans, not an attribute). Never {@code null}; an empty list when there are none.\n");
		List<DomainClass> subclasses = classes.stream().filter(d -> isStrictSubclass(d, c)).toList();
		if (!subclasses.isEmpty()) {
			b.append(" * Subtypes included or not, as is convenient: objects of ");
			b.append(String.join(", ", subclasses.stream().map(d -> "{@code " + d.getName() + "} ({@code " + objectsMethod.apply(d) + "()})").toList()));
			b.append("\n * may be listed here and in their own method; each object counts once, by type and name.\n");
		}
		return b.append(" */").toString();
	}

	/** An attribute's getter: the attribute of the class diagram, not the object's name. */
	public static String attribute(DomainClass c, Attribute a) {
		return "/** Attribute {@code " + a.getName() + "} of class {@code " + c.getName() + "} (a value set by a situation or the world)"
				+ ("name".equals(a.getName()) ? "; not the object's name, which is {@link #name()}" : "") + ". */";
	}

	/** Whether {@code sub} inherits from {@code sup}, directly or not, and is not {@code sup}. */
	public static boolean isStrictSubclass(DomainClass sub, DomainClass sup) {
		int guard = 1000; // the validator reports cyclic inheritance; never loop on it here
		for (DomainClass t = sub.getSuperType(); t != null && !t.eIsProxy() && guard-- > 0; t = t.getSuperType()) {
			if (t == sup) {
				return true;
			}
		}
		return false;
	}

	private static boolean isRobot(Actor actor) {
		return !"world".equals(kind(actor));
	}

	private static String kind(Actor actor) {
		return actor.getKind() == ActorKind.WORLD ? "world" : "robot";
	}

	private static String signature(String name, List<Parameter> params) {
		return name + "(" + String.join(", ", params.stream().map(Parameter::getName).toList()) + ")";
	}

	/** The model text of an expression, on one line, for a {@code ...} in a javadoc comment. */
	private static String javadocText(EObject e) {
		String text = NodeModelUtils.getTokenText(NodeModelUtils.findActualNodeFor(e)).replaceAll("\\s+", " ").trim();
		return text.replace("*/", "* /"); // the model's own text, but never the comment's end
	}
}
