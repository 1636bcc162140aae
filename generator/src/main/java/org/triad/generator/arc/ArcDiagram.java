package org.triad.generator.arc;

import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Connector;
import org.triad.dsl.arc.Direction;
import org.triad.dsl.arc.PortRef;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.arc.Transition;
import org.triad.dsl.semantics.ArcModels;

/**
 * A component as a Graphviz {@code dot} graph, the way MontiArc users see their models: incoming
 * ports on the left, outgoing ports on the right, each subcomponent a box with its ports, each
 * connector an arrow; an atomic component's automaton as states and labelled transitions.
 */
public class ArcDiagram {
	private static final String FONT = "fontname=\"Helvetica\"";

	public String dot(ComponentType c) {
		StringBuilder b = new StringBuilder();
		b.append("digraph ").append(quote(c.getName())).append(" {\n");
		b.append("  rankdir=LR; ").append(FONT).append("; fontsize=14; labelloc=t; nodesep=0.3; ranksep=0.9;\n");
		b.append("  label=").append(quote(signature(c))).append(";\n");
		b.append("  node [").append(FONT).append(", fontsize=11]; edge [").append(FONT).append(", fontsize=9];\n");
		ports(b, c);
		if (ArcModels.isComposed(c)) {
			for (Subcomponent s : ArcModels.subcomponents(c)) {
				b.append("  ").append(quote("sub:" + s.getName())).append(" [shape=record, style=\"rounded,filled\", fillcolor=\"#eef3fb\", label=")
						.append("\"").append(record(s).replace("\"", "\\\"")).append("\"];\n");
			}
			for (Connector con : c.getConnectors()) {
				for (PortRef target : con.getTargets()) {
					b.append("  ").append(endpoint(con.getSource(), true)).append(" -> ").append(endpoint(target, false)).append(";\n");
				}
			}
		} else {
			Automaton a = ArcModels.automaton(c);
			if (a != null) {
				automaton(b, c, a);
			} else {
				b.append("  behaviour [shape=note, label=\"hand-written behaviour\\n(").append(escape(c.getName())).append(")\"];\n");
			}
		}
		return b.append("}\n").toString();
	}

	private static void ports(StringBuilder b, ComponentType c) {
		b.append("  { rank=source;\n");
		for (ArcPort p : ArcModels.ports(c, Direction.IN)) {
			b.append("    ").append(quote("in:" + p.getName())).append(" [shape=rarrow, style=filled, fillcolor=\"#dbe8d4\", label=")
					.append(quote(p.getName() + "\n" + ArcModels.typeName(p).trim())).append("];\n");
		}
		if (ArcModels.isComposed(c) && c.getConnectors().stream().anyMatch(con -> con.getSource().isFaults())) {
			b.append("    \"in:faults\" [shape=rarrow, style=\"dashed\", label=\"faults\\n(runtime)\"];\n");
		}
		b.append("  }\n  { rank=sink;\n");
		for (ArcPort p : ArcModels.ports(c, Direction.OUT)) {
			b.append("    ").append(quote("out:" + p.getName())).append(" [shape=rarrow, style=filled, fillcolor=\"#f6e3c9\", label=")
					.append(quote(p.getName() + "\n" + ArcModels.typeName(p).trim())).append("];\n");
		}
		b.append("  }\n");
	}

	private static String signature(ComponentType c) {
		String typeParameters = c.getTypeParameters().isEmpty() ? "" : "<" + String.join(", ", ArcModels.typeParameterNames(c)) + ">";
		String parameters = c.getParameters().stream().map(p -> p.getType().trim() + " " + p.getName()).collect(Collectors.joining(", "));
		return "component " + ArcModels.qualifiedName(c) + typeParameters + (c.getParameters().isEmpty() ? "" : "(" + parameters + ")");
	}

	/** A subcomponent as a record: its incoming ports, its name and type, its outgoing ports. */
	private static String record(Subcomponent s) {
		ComponentType t = ArcModels.type(s);
		String type = t == null || t.eIsProxy() ? "?" : t.getName();
		if (!ArcModels.typeArguments(s).isEmpty()) {
			type += "<" + ArcModels.typeArguments(s).stream().map(String::trim).collect(Collectors.joining(", ")) + ">";
		}
		String middle = recordText(s.getName() + " : " + type);
		if (t == null || t.eIsProxy()) {
			return middle;
		}
		// with rankdir=LR a record's top level is vertical: the outer braces lay out in ports, name, out ports left to right
		List<ArcPort> in = ArcModels.ports(t, Direction.IN);
		List<ArcPort> out = ArcModels.ports(t, Direction.OUT);
		return "{" + (in.isEmpty() ? "" : "{" + fields(in) + "}|") + middle + (out.isEmpty() ? "" : "|{" + fields(out) + "}") + "}";
	}

	private static String fields(List<ArcPort> ports) {
		return ports.stream().map(p -> "<" + p.getName() + "> " + recordText(p.getName())).collect(Collectors.joining("|"));
	}

	private static String endpoint(PortRef ref, boolean source) {
		if (ref.isFaults()) {
			return "\"in:faults\"";
		}
		String port = ref.getPort() == null ? "?" : ref.getPort().getName();
		if (ref.getSubcomponent() == null) {
			return quote((source ? "in:" : "out:") + port);
		}
		return quote("sub:" + ref.getSubcomponent().getName()) + ":" + quote(port) + (source ? ":e" : ":w");
	}

	private static void automaton(StringBuilder b, ComponentType c, Automaton a) {
		b.append("  subgraph cluster_automaton {\n    label=\"automaton\"; style=rounded; color=\"#8a8a8a\";\n");
		b.append("    \"start\" [shape=point, width=0.12];\n");
		for (AutomatonState s : a.getStates()) {
			b.append("    ").append(quote("state:" + s.getName())).append(" [shape=box, style=\"rounded,filled\", fillcolor=\"#eef3fb\", label=")
					.append(quote(s.getName())).append("];\n");
		}
		AutomatonState initial = ArcModels.initialState(a);
		if (initial != null) {
			b.append("    \"start\" -> ").append(quote("state:" + initial.getName())).append(";\n");
		}
		for (Transition t : a.getTransitions()) {
			if (t.getSource() == null || t.getTarget() == null || t.getSource().eIsProxy() || t.getTarget().eIsProxy()) {
				continue;
			}
			b.append("    ").append(quote("state:" + t.getSource().getName())).append(" -> ").append(quote("state:" + t.getTarget().getName()))
					.append(" [label=").append(quote(label(t))).append("];\n");
		}
		b.append("  }\n");
		// invisible edges keep incoming ports left of the automaton and outgoing ports right of it
		if (initial != null) {
			for (ArcPort p : ArcModels.ports(c, Direction.IN)) {
				b.append("  ").append(quote("in:" + p.getName())).append(" -> \"start\" [style=invis];\n");
			}
		}
		for (AutomatonState s : a.getStates()) {
			for (ArcPort p : ArcModels.ports(c, Direction.OUT)) {
				b.append("  ").append(quote("state:" + s.getName())).append(" -> ").append(quote("out:" + p.getName())).append(" [style=invis];\n");
			}
		}
	}

	private static String label(Transition t) {
		StringBuilder l = new StringBuilder();
		if (t.getTrigger() != null && !t.getTrigger().eIsProxy()) {
			l.append("on ").append(t.getTrigger().getName());
		}
		if (t.getGuard() != null) {
			l.append(l.length() == 0 ? "" : " ").append("[").append(text(t.getGuard())).append("]");
		}
		return l.toString();
	}

	private static String text(org.eclipse.emf.ecore.EObject e) {
		return NodeModelUtils.getTokenText(NodeModelUtils.getNode(e));
	}

	/** Text inside a record label, where braces, bars, angle brackets and spaces are structure. */
	private static String recordText(String s) {
		return s.replaceAll("([{}|<> ])", "\\\\$1");
	}

	private static String escape(String s) {
		return s.replace("\\", "\\\\").replace("\"", "\\\"");
	}

	private static String quote(String s) {
		return "\"" + escape(s).replace("\n", "\\n") + "\"";
	}
}
