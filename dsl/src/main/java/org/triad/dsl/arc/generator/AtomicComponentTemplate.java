package org.triad.dsl.arc.generator;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.semantics.ArcModels;

/**
 * The TOP class of an atomic component (MontiArc's TOP pattern): typed ports, and one abstract
 * handler per incoming port that the hand-written subclass of the component's name implements.
 */
public class AtomicComponentTemplate {
	private final ArcNames names;

	public AtomicComponentTemplate(ArcNames names) {
		this.names = names;
	}

	public String render(ComponentType c) {
		List<ArcPort> ports = ArcModels.ports(c);
		List<ArcPort> in = ArcModels.ports(c, Direction.IN);
		StringBuilder b = new StringBuilder();
		String pkg = names.javaPackage(c);
		if (!pkg.isEmpty()) {
			b.append("package ").append(pkg).append(";\n\n");
		}
		Set<String> runtime = new LinkedHashSet<>();
		runtime.add("AtomicComponent");
		if (!in.isEmpty()) {
			runtime.add("InPort");
		}
		if (in.size() < ports.size()) {
			runtime.add("OutPort");
		}
		for (String i : JavaImports.of(c, runtime)) {
			b.append("import ").append(i).append(";\n");
		}
		b.append("\n/**\n * Interface of component {@code ").append(ArcModels.qualifiedName(c)).append("}, generated from its .arc model; do not edit.\n")
				.append(" * Its behavior is the hand-written subclass {@code ").append(names.componentClass(c))
				.append("}: one handler per incoming port (TOP pattern).\n").append(JavaDoc.paragraph(ArcModels.documentation(c))).append(" */\n");
		if (ports.stream().anyMatch(names::isGeneric)) {
			b.append("@SuppressWarnings(\"unchecked\")\n");
		}
		String top = names.topClass(c);
		b.append("public abstract class ").append(top).append(" extends AtomicComponent {\n");
		for (ArcPort p : ports) {
			b.append(port(p));
		}
		b.append("\n    protected ").append(top).append("() {\n");
		for (ArcPort p : in) {
			b.append("        on(").append(names.portField(p)).append(", this::").append(names.handler(p)).append(");\n");
		}
		b.append("    }\n");
		for (ArcPort p : in) {
			b.append(handler(p));
		}
		b.append("}\n");
		return b.toString();
	}

	private String port(ArcPort p) {
		boolean in = ArcModels.direction(p) == Direction.IN;
		return "    public final " + (in ? "InPort<" : "OutPort<") + names.portTypeArgument(p) + "> " + names.portField(p) + " = "
				+ (in ? "inPort(\"" : "outPort(\"") + names.runtimePortName(p) + "\", " + names.classLiteral(p) + ");\n";
	}

	private String handler(ArcPort p) {
		return "\n    protected abstract void " + names.handler(p) + "(" + names.portTypeArgument(p) + " " + names.handlerParameter()
				+ ") throws Exception;\n";
	}
}
