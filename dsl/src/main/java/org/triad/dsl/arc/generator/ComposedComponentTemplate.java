package org.triad.dsl.arc.generator;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.ConfigParameter;
import org.triad.dsl.arc.Connector;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.arc.PortRef;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.semantics.ArcModels;

/**
 * The wiring class of a composed component: its ports, one field per subcomponent created from the
 * configuration parameters, and one method that makes every connection.
 */
public class ComposedComponentTemplate {
	private final ArcNames names;

	public ComposedComponentTemplate(ArcNames names) {
		this.names = names;
	}

	public String render(ComponentType c) {
		List<ArcPort> ports = ArcModels.ports(c);
		long in = ports.stream().filter(p -> ArcModels.direction(p) == Direction.IN).count();
		StringBuilder b = new StringBuilder();
		String pkg = names.javaPackage(c);
		if (!pkg.isEmpty()) {
			b.append("package ").append(pkg).append(";\n\n");
		}
		Set<String> runtime = new LinkedHashSet<>();
		runtime.add("ComposedComponent");
		if (in > 0) {
			runtime.add("InPort");
		}
		if (in < ports.size()) {
			runtime.add("OutPort");
		}
		for (String i : JavaImports.of(c, runtime)) {
			b.append("import ").append(i).append(";\n");
		}
		b.append("\n/**\n * Component {@code ").append(ArcModels.qualifiedName(c))
				.append("}, generated from its .arc model; do not edit: ports, subcomponents and connectors.\n")
				.append(JavaDoc.paragraph(ArcModels.documentation(c))).append(" */\n");
		if (ports.stream().anyMatch(names::isGeneric)) {
			b.append("@SuppressWarnings(\"unchecked\")\n");
		}
		String cls = names.componentClass(c);
		b.append("public class ").append(cls).append(" extends ComposedComponent {\n");
		for (ArcPort p : ports) {
			b.append(port(p));
		}
		b.append("\n");
		for (Subcomponent s : c.getSubcomponents()) {
			b.append("    public final ").append(subcomponentClass(c, s)).append(" ").append(names.subcomponentField(s)).append(";\n");
		}
		b.append("\n    public ").append(cls).append("(").append(parameters(c)).append(") {\n");
		for (Subcomponent s : c.getSubcomponents()) {
			b.append("        ").append(names.subcomponentField(s)).append(" = subcomponent(\"").append(s.getName()).append("\", new ")
					.append(subcomponentClass(c, s)).append("(").append(String.join(", ", s.getArguments())).append("));\n");
		}
		b.append("        ").append(names.connectMethod()).append("();\n    }\n\n");
		b.append("    private void ").append(names.connectMethod()).append("() {\n");
		for (Connector con : c.getConnectors()) {
			b.append(connector(con));
		}
		b.append("    }\n}\n");
		return b.toString();
	}

	private String port(ArcPort p) {
		boolean in = ArcModels.direction(p) == Direction.IN;
		return "    public final " + (in ? "InPort<" : "OutPort<") + names.portTypeArgument(p) + "> " + names.portField(p) + " = "
				+ (in ? "inPort(\"" : "outPort(\"") + names.runtimePortName(p) + "\", " + names.classLiteral(p) + ");\n";
	}

	private String parameters(ComponentType c) {
		return c.getParameters().stream().map((ConfigParameter p) -> p.getType() + " " + names.parameter(p.getName()))
				.collect(Collectors.joining(", "));
	}

	private String subcomponentClass(ComponentType owner, Subcomponent s) {
		ComponentType type = s.getType();
		return names.javaPackage(type).equals(names.javaPackage(owner)) ? names.componentClass(type) : names.qualifiedComponentClass(type);
	}

	private String connector(Connector con) {
		return "        connect(" + endpoint(con.getSource()) + ", "
				+ con.getTargets().stream().map(this::endpoint).collect(Collectors.joining(", ")) + ");\n";
	}

	private String endpoint(PortRef ref) {
		if (ref.isFaults()) {
			return names.faultsField();
		}
		String port = names.portField(ref.getPort());
		return ref.getSubcomponent() == null ? port : names.subcomponentField(ref.getSubcomponent()) + "." + port;
	}
}
