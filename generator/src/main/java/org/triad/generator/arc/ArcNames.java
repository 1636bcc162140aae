package org.triad.generator.arc;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.triad.dsl.arc.ArcNamedElement;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.semantics.ArcModels;
import org.triad.dsl.typing.ArcTypes;

/**
 * Every name the architecture generator emits. As in MontiArc, a component's Java package is its
 * .arc package, and the class that instantiates a component always has the component's name: the
 * generated class itself, or, where hand-written code of that name exists, the hand-written
 * subclass of the generated {@link #topClass TOP class}.
 */
public class ArcNames {
	private DataTypes dataTypes = DataTypes.NONE;
	public static final String RUNTIME_PACKAGE = "org.triad.runtime.component";
	/** Transitions without a trigger taken in a row before the automaton is considered to loop. */
	public static final int MAX_COMPLETIONS = 1000;
	private static final Set<String> JAVA_KEYWORDS = Set.of("abstract", "assert", "boolean", "break", "byte", "case", "catch", "char",
			"class", "const", "continue", "default", "do", "double", "else", "enum", "extends", "final", "finally", "float", "for", "goto",
			"if", "implements", "import", "instanceof", "int", "interface", "long", "native", "new", "package", "private", "protected",
			"public", "return", "short", "static", "strictfp", "super", "switch", "synchronized", "this", "throw", "throws", "transient",
			"try", "void", "volatile", "while", "true", "false", "null", "var", "record", "yield");
	private static final Map<String, String> BOXES = Map.of("boolean", "Boolean", "int", "Integer", "long", "Long", "double", "Double",
			"float", "Float", "short", "Short", "byte", "Byte", "char", "Character");

	public String javaPackage(ComponentType c) {
		return ArcModels.packageName(c);
	}

	/** The generated class where hand-written code extends it (MontiArc's TOP pattern). */
	public String topClass(ComponentType c) {
		return c.getName() + "TOP";
	}

	/** The class that instantiates a component: the hand-written class if there is one, otherwise the generated one. */
	public String componentClass(ComponentType c) {
		return c.getName();
	}

	public String qualifiedComponentClass(ComponentType c) {
		return qualified(javaPackage(c), componentClass(c));
	}

	public String qualified(String pkg, String simpleName) {
		return pkg.isEmpty() ? simpleName : pkg + "." + simpleName;
	}

	/** The Java file of a class, relative to the output folder. */
	public String javaFile(ComponentType c, String simpleClassName) {
		String pkg = javaPackage(c);
		return (pkg.isEmpty() ? "" : pkg.replace('.', '/') + "/") + simpleClassName + ".java";
	}

	/** {@code <T, U>} for a generic component, "" otherwise. */
	public String typeParameters(ComponentType c) {
		List<String> ps = ArcModels.typeParameterNames(c);
		return ps.isEmpty() ? "" : "<" + String.join(", ", ps) + ">";
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

	/** A configuration parameter, variable or port as a Java field or parameter. */
	public String field(ArcNamedElement e) {
		return identifier(e.getName());
	}

	public String parameter(String name) {
		return identifier(name);
	}

	public String handler(ArcPort p) {
		return "on" + Character.toUpperCase(p.getName().charAt(0)) + p.getName().substring(1);
	}

	/** The handler's parameter: the message, named like its port so guards and actions read it by the port's name. */
	public String handlerParameter(ArcPort p) {
		return identifier(p.getName());
	}

	/** The handler parameter of a hand-written behaviour (no automaton). */
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

	public String stateEnum() {
		return "State";
	}

	public String stateConstant(AutomatonState s) {
		return identifier(s.getName());
	}

	public String stateField() {
		return "state";
	}

	public String currentStateMethod() {
		return "currentState";
	}

	public String startedField() {
		return "started";
	}

	public String startMethod() {
		return "start";
	}

	public String completeMethod() {
		return "completeTransitions";
	}

	public String completeOnceMethod() {
		return "completeTransition";
	}

	public String unhandledMethod() {
		return "unhandled";
	}

	/** The type argument of a port: the model's type with primitives boxed. */
	public String portTypeArgument(ArcPort p) {
		String t = javaType(ArcModels.typeName(p).trim());
		return BOXES.getOrDefault(t, t);
	}

	/** A {@code Class<T>} expression for a port type; generic types and type parameters need an unchecked cast. */
	public String classLiteral(ArcPort p) {
		String t = portTypeArgument(p);
		ComponentType c = ArcModels.component(p);
		if (ArcModels.typeParameterNames(c).contains(ArcTypes.erasure(t))) {
			return "(Class<" + t + ">) (Class<?>) Object.class";
		}
		if (isGeneric(p)) {
			return "(Class<" + t + ">) (Class<?>) " + ArcTypes.erasure(t) + ".class";
		}
		return t + ".class";
	}

	/** Whether the port's class literal needs an unchecked cast. */
	public boolean isGeneric(ArcPort p) {
		String t = portTypeArgument(p);
		return t.contains("<") || ArcModels.typeParameterNames(ArcModels.component(p)).contains(ArcTypes.erasure(t));
	}

	/**
	 * A type name of the model as Java: a class diagram's data type is written {@code p.Diagram.Type} in
	 * MontiArc and generated as {@code p.Type} (the diagram's package holds its types).
	 */
	public String javaType(String modelType) {
		return dataTypes.javaType(modelType);
	}

	/** A subcomponent argument (opaque Java text) with data type names as Java. */
	public String javaArgument(String argument) {
		return dataTypes.javaType(argument);
	}

	/** The class diagrams whose types the models name. */
	public void useDataTypes(DataTypes types) {
		this.dataTypes = types;
	}

	public DataTypes dataTypes() {
		return dataTypes;
	}

	public String timedStateField() {
		return "state";
	}

	static String identifier(String name) {
		return JAVA_KEYWORDS.contains(name) ? name + "_" : name;
	}
}
