package org.triad.generator.arc;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Enumeration;

/**
 * The data types an architecture takes from class diagrams (MontiArc's {@code .cd} files): each
 * enumeration becomes a Java enum in the diagram's package, and the models' names for it
 * ({@code p.Diagram.T}) become Java's ({@code p.T}).
 */
public final class DataTypes {
	public static final DataTypes NONE = new DataTypes(Map.of());
	private static final Pattern PACKAGE = Pattern.compile("^\\s*(?:/\\*.*?\\*/\\s*|//[^\\n]*\\n\\s*)*package\\s+([\\w.]+)\\s*;", Pattern.DOTALL);

	/** Diagram qualified name (p.Diagram, or Diagram) to its Java package (p, or ""). */
	private final Map<String, String> diagrams;
	private final Map<String, ClassDiagram> byName = new HashMap<>();

	private DataTypes(Map<String, String> diagrams) {
		this.diagrams = diagrams;
	}

	public static DataTypes of(List<ClassDiagram> cds) {
		Map<String, String> diagrams = new HashMap<>();
		DataTypes types = new DataTypes(diagrams);
		for (ClassDiagram cd : cds) {
			String pkg = packageOf(cd);
			String qualified = pkg.isEmpty() ? cd.getName() : pkg + "." + cd.getName();
			diagrams.put(qualified, pkg);
			types.byName.put(qualified, cd);
		}
		return types;
	}

	/** The package a class diagram declares ({@code package p;}), "" without one. */
	public static String packageOf(ClassDiagram cd) {
		ICompositeNode node = NodeModelUtils.getNode(cd);
		if (node == null) {
			return "";
		}
		Matcher m = PACKAGE.matcher(node.getText());
		return m.find() ? m.group(1) : "";
	}

	/** Rewrites every {@code p.Diagram.} in a type name or Java text to {@code p.}. */
	public String javaType(String text) {
		String result = text;
		for (Map.Entry<String, String> d : diagrams.entrySet()) {
			String from = d.getKey() + ".";
			String to = d.getValue().isEmpty() ? "" : d.getValue() + ".";
			result = result.replace(from, to);
		}
		return result;
	}

	public String javaImport(String imported) {
		if (diagrams.containsKey(imported.replaceFirst("\\.\\*$", ""))) {
			String pkg = diagrams.get(imported.replaceFirst("\\.\\*$", ""));
			return imported.endsWith(".*") ? (pkg.isEmpty() ? "" : pkg + ".*") : imported;
		}
		return javaType(imported);
	}

	/** The Java enums of the diagrams: path relative to the output folder, and source. */
	public Map<String, String> files() {
		Map<String, String> files = new HashMap<>();
		for (Map.Entry<String, ClassDiagram> e : byName.entrySet()) {
			String pkg = diagrams.get(e.getKey());
			for (DomainType t : e.getValue().getTypes()) {
				if (t instanceof Enumeration en) {
					StringBuilder b = new StringBuilder();
					if (!pkg.isEmpty()) {
						b.append("package ").append(pkg).append(";\n\n");
					}
					b.append("/** Enumeration {@code ").append(t.getName()).append("} of class diagram {@code ").append(e.getKey())
							.append("}, generated; do not edit. */\npublic enum ").append(t.getName()).append(" {\n");
					List<EnumLiteral> literals = en.getLiterals();
					for (int i = 0; i < literals.size(); i++) {
						b.append("\t").append(literals.get(i).getName()).append(i + 1 < literals.size() ? ",\n" : "\n");
					}
					b.append("}\n");
					files.put((pkg.isEmpty() ? "" : pkg.replace('.', '/') + "/") + t.getName() + ".java", b.toString());
				}
			}
		}
		return files;
	}
}
