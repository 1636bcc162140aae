package org.triad.generator.java;

import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import javax.lang.model.SourceVersion;

import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Application;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.EnumLiteral;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.TypeRef;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * Every name the Java generator emits: packages, classes, methods, fields and variables. Model names
 * become Java identifiers here (a Java keyword gets a trailing {@code _}, and so does a member that
 * would clash with a member the generated class already has), so the templates never derive a name
 * themselves.
 */
public final class TriadNames {
	/** Members of {@link Object} a generated method must not override or hide by accident. */
	private static final Set<String> OBJECT_MEMBERS = Set.of("getClass", "hashCode", "equals", "toString", "clone", "finalize",
			"notify", "notifyAll", "wait");
	/** Members of the generated goal and task classes besides the model's parameters. */
	private static final Set<String> INSTANCE_MEMBERS = Set.of("name", "args", "goals", "describe", "isSatisfiedIn", "binding",
			"CONDITION", "EVALUATOR", "NAME");

	private final Application app;
	private final String basePackage;

	public TriadNames(Application app, String basePackage) {
		if (basePackage == null || basePackage.isBlank() || !SourceVersion.isName(basePackage)) {
			throw new IllegalArgumentException("not a Java package name: '" + basePackage + "'");
		}
		this.app = app;
		this.basePackage = basePackage;
	}

	/** {@code generated.<application name in lower case>}. */
	public static String defaultBasePackage(Application app) {
		return "generated." + identifier(app.getName().toLowerCase(Locale.ROOT));
	}

	// ---- packages and classes ------------------------------------------------------------------

	public String basePackage() {
		return basePackage;
	}

	public String domainPackage() {
		return basePackage + ".domain";
	}

	public String goalsPackage() {
		return basePackage + ".goals";
	}

	public String tasksPackage() {
		return basePackage + ".tasks";
	}

	/** The application's name as the prefix of its generated classes, e.g. {@code Logistics}. */
	public String applicationPrefix() {
		return upperFirst(identifier(app.getName()));
	}

	public String robotInterface() {
		return "IRobot";
	}

	public String worldInterface() {
		return "IWorld";
	}

	public String schemaClass() {
		return applicationPrefix() + "Schema";
	}

	public String stateProviderClass() {
		return applicationPrefix() + "StateProvider";
	}

	public String actionExecutorClass() {
		return applicationPrefix() + "ActionExecutor";
	}

	public String domainClass(DomainType t) {
		return identifier(t.getName());
	}

	public String goalClass(Goal g) {
		return identifier(g.getName());
	}

	public String taskClass(Task t) {
		return identifier(t.getName());
	}

	public String qualified(String pkg, String simpleName) {
		return pkg + "." + simpleName;
	}

	public String qualifiedDomainClass(DomainType t) {
		return qualified(domainPackage(), domainClass(t));
	}

	public String qualifiedGoalClass(Goal g) {
		return qualified(goalsPackage(), goalClass(g));
	}

	public String qualifiedTaskClass(Task t) {
		return qualified(tasksPackage(), taskClass(t));
	}

	public String qualifiedRobotInterface() {
		return qualified(basePackage, robotInterface());
	}

	public String qualifiedWorldInterface() {
		return qualified(basePackage, worldInterface());
	}

	public String qualifiedSchemaClass() {
		return qualified(basePackage, schemaClass());
	}

	public String qualifiedStateProviderClass() {
		return qualified(basePackage, stateProviderClass());
	}

	public String qualifiedActionExecutorClass() {
		return qualified(basePackage, actionExecutorClass());
	}

	/** The entry point that builds the application's RefArc around its robot and world ({@code HospitalRefArc.of(robot, world)}). */
	public String refArcClass() {
		return applicationPrefix() + "RefArc";
	}

	public String qualifiedRefArcClass() {
		return qualified(basePackage, refArcClass());
	}

	/** The simple names of the classes generated into a package, which shadow imported names there. */
	public Set<String> classesIn(String pkg) {
		Set<String> names = new HashSet<>();
		if (pkg.equals(domainPackage()) && app.getDomain() != null) {
			app.getDomain().getTypes().forEach(t -> names.add(domainClass(t)));
		} else if (pkg.equals(goalsPackage())) {
			app.getGoals().forEach(g -> names.add(goalClass(g)));
		} else if (pkg.equals(tasksPackage())) {
			app.getTasks().forEach(t -> names.add(taskClass(t)));
		} else if (pkg.equals(basePackage)) {
			names.addAll(List.of(robotInterface(), worldInterface(), schemaClass(), stateProviderClass(), actionExecutorClass(), refArcClass()));
		}
		return names;
	}

	/** An import manager for one generated compilation unit. */
	public Imports imports(String pkg, String simpleName) {
		return new Imports(pkg, simpleName, classesIn(pkg));
	}

	// ---- types ---------------------------------------------------------------------------------

	/** The Java type of a model type: a primitive, {@code java.lang.String}, or a generated domain class (qualified). */
	public String javaType(TypeRef ref) {
		TriadType t = TriadTypeSystem.typeOf(ref);
		return switch (t.kind()) {
			case BOOLEAN -> "boolean";
			case INT -> "int";
			case DOUBLE -> "double";
			case STRING -> "java.lang.String";
			case CLASS, ENUM -> qualifiedDomainClass(t.domainType());
			case UNKNOWN -> throw new IllegalArgumentException("unresolved type in the model: check the models before generating");
		};
	}

	/** {@link #javaType} with primitives boxed, for generics and casts. */
	public String boxedJavaType(TypeRef ref) {
		return switch (javaType(ref)) {
			case "boolean" -> "java.lang.Boolean";
			case "int" -> "java.lang.Integer";
			case "double" -> "java.lang.Double";
			default -> javaType(ref);
		};
	}

	// ---- members of domain classes -------------------------------------------------------------

	public String field(Attribute a) {
		return identifier(a.getName());
	}

	public String getter(Attribute a) {
		return member((isBoolean(a.getType()) ? "is" : "get") + upperFirst(a.getName()));
	}

	public String setter(Attribute a) {
		return member("set" + upperFirst(a.getName()));
	}

	public String enumConstant(EnumLiteral l) {
		return identifier(l.getName());
	}

	/** The method that names a domain object's most specific class. */
	public String typeNameMethod() {
		return "typeName";
	}

	/** The constructor parameter of domain classes. */
	public String objectNameParameter() {
		return "name";
	}

	// ---- members of IRobot and IWorld ----------------------------------------------------------

	public String propertyMethod(Property p) {
		return member(identifier(p.getName()));
	}

	public String actionMethod(Action a) {
		return member(identifier(a.getName()));
	}

	/** A parameter of an action, property, goal or task as a Java parameter or local variable. */
	public String parameter(Parameter p) {
		return identifier(p.getName());
	}

	/**
	 * The world's method listing the objects of a class that exist now, e.g. {@code rooms()} for
	 * {@code Room}; prefixed with {@code all} if the world already has a member of that name.
	 */
	public String objectsMethod(DomainClass c) {
		String plural = member(lowerFirst(identifier(plural(c.getName()))));
		Actor world = app.getWorld();
		boolean taken = world != null && (world.getProperties().stream().anyMatch(p -> propertyMethod(p).equals(plural))
				|| world.getActions().stream().anyMatch(a -> actionMethod(a).equals(plural)));
		return taken ? "all" + upperFirst(plural) : plural;
	}

	// ---- members of goal and task classes ------------------------------------------------------

	public String goalField(Parameter p) {
		String id = identifier(p.getName());
		return INSTANCE_MEMBERS.contains(id) ? id + "_" : id;
	}

	public String goalGetter(Parameter p) {
		return member("get" + upperFirst(p.getName()));
	}

	public String conditionConstant() {
		return "CONDITION";
	}

	public String evaluatorConstant() {
		return "EVALUATOR";
	}

	public String nameConstant() {
		return "NAME";
	}

	/** The parameter of {@code isSatisfiedIn}. */
	public String stateParameter() {
		return "state";
	}

	// ---- the schema class and the component behaviours ------------------------------------------

	public String schemaField() {
		return "SCHEMA";
	}

	public String schemaPartMethod(String part) {
		return part;
	}

	public String robotField() {
		return "robot";
	}

	public String worldField() {
		return "world";
	}

	/** A local variable of the state provider holding the objects of a class that may be arguments. */
	public String candidatesVariable(DomainClass c) {
		return lowerFirst(identifier(plural(c.getName()))) + "Candidates";
	}

	/** The loop variable for the i-th argument of a property in the state provider. */
	public String argumentVariable(int i) {
		return "arg" + i;
	}

	// ---- locals and helpers inside generated methods (fixed: model names never reach them) ----

	public String stateBuilderVariable() {
		return "builder";
	}

	public String objectsVariable() {
		return "objects";
	}

	public String bindingVariable() {
		return "binding";
	}

	/** The executor's table of typed method references, one per action. */
	public String actionTableField() {
		return "actions";
	}

	/** The typed arguments of an action with more than six parameters. */
	public String argumentsVariable() {
		return "args";
	}

	/** A goal's parameters by name, bound once when the goal is made. */
	public String goalBindingField() {
		return "binding";
	}

	public String transitionsField() {
		return "transitions";
	}

	public String actionParameter() {
		return "action";
	}

	public String nowParameter() {
		return "now";
	}

	public String conjunctVariable() {
		return "part";
	}

	public String actorVariable() {
		return "actor";
	}

	public String explainingVariable() {
		return "explaining";
	}

	public String actionSchemaVariable() {
		return "schema";
	}

	public String schemaBuilderVariable() {
		return "b";
	}

	public String schemaBuildMethod() {
		return "build";
	}

	/** The state provider's helper selecting the objects of a class. */
	public String ofTypeMethod() {
		return "ofType";
	}

	// ---- rules -------------------------------------------------------------------------------

	public static boolean isBoolean(TypeRef ref) {
		return TriadTypeSystem.typeOf(ref).kind() == TriadType.Kind.BOOLEAN;
	}

	/** A Java identifier for a model name: invalid characters become {@code _}, keywords get a trailing {@code _}. */
	public static String identifier(String raw) {
		if (raw == null || raw.isEmpty()) {
			return "_";
		}
		StringBuilder b = new StringBuilder();
		for (int i = 0; i < raw.length(); i++) {
			char c = raw.charAt(i);
			b.append(i == 0 ? (Character.isJavaIdentifierStart(c) ? c : Character.isJavaIdentifierPart(c) ? "_" + c : "_")
					: Character.isJavaIdentifierPart(c) ? c : '_');
		}
		String id = b.toString();
		return SourceVersion.isKeyword(id) || id.equals("_") ? id + "_" : id;
	}

	private static String member(String name) {
		return OBJECT_MEMBERS.contains(name) || SourceVersion.isKeyword(name) ? name + "_" : name;
	}

	static String plural(String noun) {
		if (noun.matches(".*[^aeiouAEIOU]y")) {
			return noun.substring(0, noun.length() - 1) + "ies";
		}
		if (noun.endsWith("s") || noun.endsWith("x") || noun.endsWith("z") || noun.endsWith("ch") || noun.endsWith("sh")) {
			return noun + "es";
		}
		return noun + "s";
	}

	static String upperFirst(String s) {
		return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
	}

	static String lowerFirst(String s) {
		return s.isEmpty() ? s : Character.toLowerCase(s.charAt(0)) + s.substring(1);
	}
}
