package org.triad.dsl.validation;

/**
 * Stable codes of diagnostics shared by every Triad language: syntax, unresolved names,
 * expressions and application-wide rules. Codes never change once published; a rule that goes
 * away leaves its code unused.
 */
public final class CommonIssueCodes {
	private CommonIssueCodes() {
	}

	public static final String SYNTAX = "syntax";

	public static final String UNKNOWN_DOMAIN = "link.unknown-domain";
	public static final String UNKNOWN_TYPE = "link.unknown-type";
	public static final String UNKNOWN_ACTOR = "link.unknown-actor";
	public static final String UNKNOWN_PROPERTY = "link.unknown-property";
	public static final String UNKNOWN_GOAL = "link.unknown-goal";
	public static final String UNKNOWN_VALUE = "link.unknown-parameter";
	public static final String UNKNOWN_ENUMERATION = "link.unknown-enumeration";
	public static final String UNKNOWN_LITERAL = "link.unknown-literal";
	public static final String UNKNOWN_ATTRIBUTE = "link.unknown-attribute";
	/** {@code r.weight} where {@code weight} is an attribute of another class than r's (and not of r's superclasses). */
	public static final String ATTRIBUTE_OF_OTHER_CLASS = "link.attribute-of-other-class";
	public static final String UNKNOWN_NAME = "link.unknown-name";
	/** {@code state B extends A} where the application has no situation {@code A}. */
	public static final String UNKNOWN_SITUATION = "link.unknown-situation";
	/** A property call outside an actor that does not name the actor. */
	public static final String UNQUALIFIED_CALL = "expr.unqualified-call";

	/** An operand of {@code &&}, {@code ||} or {@code !} that is not Boolean. */
	public static final String NOT_BOOLEAN_OPERAND = "expr.not-boolean";
	/** A condition (precondition, postcondition, goal situation, fact) that is not Boolean. */
	public static final String CONDITION_NOT_BOOLEAN = "expr.condition-not-boolean";
	/** {@code ==}/{@code !=} between values of incompatible types. */
	public static final String INCOMPATIBLE_OPERANDS = "expr.incompatible-operands";
	/** An ordering comparison ({@code < <= > >=}) or arithmetic ({@code + - * /}) on values that are not numbers. */
	public static final String NOT_NUMERIC = "expr.not-numeric";
	/** A Boolean property passed as the argument of a property: the planner passes objects and values, not conditions. */
	public static final String CONDITION_AS_ARGUMENT = "plan.condition-as-argument";
	// "expr.attribute-read" (an attribute read at all) is retired: 'b.weight' reads the attribute now
	/** A division by a divisor that is zero ({@code x / 0}, {@code x / (2 - 2)}). */
	public static final String DIVISION_BY_ZERO = "expr.division-by-zero";
	/** Arithmetic on literals whose result is not a finite number of its type (an int past 2147483647, a double past 1.8e308). */
	public static final String OVERFLOW = "expr.overflow";
	/** {@code p()@pre} (the value before the action) outside the value of a postcondition's effect. */
	public static final String PRE_OUTSIDE_POSTCONDITION = "expr.pre-outside-post";
	/**
	 * A number parameter of an action combined with a quantity (a number the planner computes with, such
	 * as a battery level): numeric planning (PDDL 2.1) chooses objects for parameters, never numbers.
	 */
	public static final String NUMBER_PARAMETER = "plan.number-parameter";
	/** A quantity read inside the argument of another property: its value is a number the planner computes, not an object. */
	public static final String QUANTITY_AS_ARGUMENT = "plan.quantity-as-argument";
	/** A property call with the wrong number of arguments. */
	public static final String ARGUMENT_COUNT = "expr.argument-count";
	/** A property call argument whose type does not fit the parameter. */
	public static final String ARGUMENT_TYPE = "expr.argument-type";

	/**
	 * An expression deeper than the parser reads ({@link org.triad.dsl.parser.ExpressionLimits}):
	 * nested parentheses, negations or call arguments, or a chain of operators, past the limit.
	 */
	public static final String EXPRESSION_TOO_DEEP = "expr.too-deep";

	/** Two parameters of one property, action, goal or task with the same name. */
	public static final String DUPLICATE_PARAMETER = "common.duplicate-parameter";
	/** Two elements of the application (class diagrams, actors, goals, tasks, situations) with the same name. */
	public static final String DUPLICATE_NAME = "app.duplicate-name";
	// "app.structure" (retired, never to be reused) became CLASS_DIAGRAM_COUNT, ROBOT_COUNT and WORLD_COUNT,
	// one code per rule of org.triad.dsl.app.ApplicationStructure.
	/** An application without a class diagram or with more than one (the class diagram names the application). */
	public static final String CLASS_DIAGRAM_COUNT = "app.class-diagram-count";
	/** An application without a robot actor (several robots: {@link ActorIssueCodes#DUPLICATE_KIND}). */
	public static final String ROBOT_COUNT = "app.robot-count";
	/** An application without a world actor (several worlds: {@link ActorIssueCodes#DUPLICATE_KIND}). */
	public static final String WORLD_COUNT = "app.world-count";
}
