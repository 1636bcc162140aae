package org.triad.dsl.arc.generator;

import java.util.Map;
import java.util.Set;

import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.typing.ArcTypes;

/**
 * Every name the architecture generator emits: Java packages and classes of components, fields of
 * ports and subcomponents, handler methods. The Java package of a component is its .arc package
 * under an optional base package (base {@code org.triad} puts {@code refarc.RefArc} in
 * {@code org.triad.refarc}).
 */
public class ArcNames {
	public static final String RUNTIME_PACKAGE = "org.triad.runtime.component";
	private static final Set<String> JAVA_KEYWORDS = Set.of("abstract", "assert", "boolean", "break", "byte", "case", "catch", "char",
			"class", "const", "continue", "default", "do", "double", "else", "enum", "extends", "final", "finally", "float", "for", "goto",
			"if", "implements", "import", "instanceof", "int", "interface", "long", "native", "new", "package", "private", "protected",
			"public", "return", "short", "static", "strictfp", "super", "switch", "synchronized", "this", "throw", "throws", "transient",
			"try", "void", "volatile", "while", "true", "false", "null", "var", "record", "yield");
	private static final Map<String, String> BOXES = Map.of("boolean", "Boolean", "int", "Integer", "long", "Long", "double", "Double",
			"float", "Float", "short", "Short", "byte", "Byte", "char", "Character");

	private final String basePackage;

	public ArcNames() {
		this("");
	}

	public ArcNames(String basePackage) {
		this.basePackage = basePackage == null ? "" : basePackage;
	}

	public String javaPackage(ComponentType c) {
		return javaPackageOf(ArcModels.packageName(c));
	}

	/** The Java package of an .arc package. */
	public String javaPackageOf(String arcPackage) {
		if (basePackage.isEmpty()) {
			return arcPackage;
		}
		return arcPackage.isEmpty() ? basePackage : basePackage + "." + arcPackage;
	}

	/** Generated base class of an atomic component; its behavior is the hand-written subclass {@link #componentClass}. */
	public String topClass(ComponentType c) {
		return c.getName() + "TOP";
	}

	/** The class that instantiates a component: the hand-written subclass of an atomic one, the generated class of a composed one. */
	public String componentClass(ComponentType c) {
		return c.getName();
	}

	public String qualifiedComponentClass(ComponentType c) {
		String pkg = javaPackage(c);
		return pkg.isEmpty() ? componentClass(c) : pkg + "." + componentClass(c);
	}

	/** The Java file of a class, relative to the output folder. */
	public String javaFile(ComponentType c, String simpleClassName) {
		String pkg = javaPackage(c);
		return (pkg.isEmpty() ? "" : pkg.replace('.', '/') + "/") + simpleClassName + ".java";
	}

	public String portField(ArcPort p) {
		return identifier(p.getName());
	}

	/** The port's name at runtime (what {@code Component.port(name)} and fault messages show). */
	public String runtimePortName(ArcPort p) {
		return p.getName();
	}

	public String subcomponentField(Subcomponent s) {
		return identifier(s.getName());
	}

	public String parameter(String name) {
		return identifier(name);
	}

	public String handler(ArcPort p) {
		return "on" + Character.toUpperCase(p.getName().charAt(0)) + p.getName().substring(1);
	}

	public String handlerParameter() {
		return "message";
	}

	public String connectMethod() {
		return "connectPorts";
	}

	/** The composed component's runtime-fed fault port field ({@code ComposedComponent.faults}). */
	public String faultsField() {
		return "faults";
	}

	/** The type argument of a port: the model's type with primitives boxed. */
	public String portTypeArgument(ArcPort p) {
		String t = ArcModels.typeName(p).trim();
		return BOXES.getOrDefault(t, t);
	}

	/** A {@code Class<T>} expression for a port type; generic types need an unchecked cast. */
	public String classLiteral(ArcPort p) {
		String t = portTypeArgument(p);
		if (isGeneric(p)) {
			return "(Class<" + t + ">) (Class<?>) " + ArcTypes.erasure(t) + ".class";
		}
		return t + ".class";
	}

	public boolean isGeneric(ArcPort p) {
		return portTypeArgument(p).contains("<");
	}

	private static String identifier(String name) {
		return JAVA_KEYWORDS.contains(name) ? name + "_" : name;
	}
}
