package org.triad.dsl.validation;

/** Stable codes of diagnostics of architecture models ({@code .arc}). Syntax errors use {@link CommonIssueCodes#SYNTAX}. */
public final class ArcIssueCodes {
	private ArcIssueCodes() {
	}

	/** A subcomponent's type names no component (by qualified name, import or same package). */
	public static final String UNKNOWN_COMPONENT = "arc.unknown-component";
	/** A connector names a port the component or the subcomponent's type does not have. */
	public static final String UNKNOWN_PORT = "arc.unknown-port";
	/** {@code sub.port} names no subcomponent of this component. */
	public static final String UNKNOWN_SUBCOMPONENT = "arc.unknown-subcomponent";
	/** A transition names a state its automaton does not declare. */
	public static final String UNKNOWN_STATE = "arc.unknown-state";
	/**
	 * A connector's source is not an incoming port of the component or an outgoing port of a
	 * subcomponent, or its target is not an outgoing port of the component or an incoming port of a
	 * subcomponent.
	 */
	public static final String DIRECTION_MISMATCH = "arc.direction-mismatch";
	/** A connector joins ports whose types are not assignable (by name, or the known assignability table). */
	public static final String TYPE_MISMATCH = "arc.type-mismatch";
	/** A port is the target of more than one connector. */
	public static final String TWO_SENDERS = "arc.two-senders";
	/** An atomic component (one without subcomponents) has connectors. */
	public static final String CONNECTOR_IN_ATOMIC = "arc.connector-in-atomic";
	/** A guard or action names something that is not a variable, configuration parameter or port of its component. */
	public static final String UNKNOWN_NAME = "arc.unknown-name";
	/** An automaton has states but none is {@code initial}: the component would not know where to start. */
	public static final String NO_INITIAL_STATE = "arc.no-initial-state";
	public static final String MULTIPLE_INITIAL_STATES = "arc.multiple-initial-states";
	/** A component has more than one automaton block. */
	public static final String MULTIPLE_AUTOMATA = "arc.multiple-automata";
	/** A component contains itself, directly or through other components. */
	public static final String INSTANTIATION_CYCLE = "arc.instantiation-cycle";
	/**
	 * Two parameters, ports or subcomponents of one component, two states of one automaton, or two
	 * components with the same qualified name.
	 */
	public static final String DUPLICATE_NAME = "arc.duplicate-name";
	/**
	 * Warning: an incoming port of a subcomponent or an outgoing port of a composed component that
	 * no connector sends to; it never gets a message.
	 */
	public static final String UNCONNECTED_PORT = "arc.unconnected-port";
	/** A subcomponent gets a different number of arguments than its type has configuration parameters. */
	public static final String ARGUMENT_COUNT = "arc.argument-count";
	/** Warning: no chain of transitions leads from the initial state to this state. */
	public static final String UNREACHABLE_STATE = "arc.unreachable-state";
	/**
	 * Two transitions leave one state on the same trigger (or both without one) and both can fire: at
	 * least one has no guard, or their guards are the same text. Guards that overlap otherwise are not
	 * detected (that needs a solver); the generated code takes the first in model order.
	 */
	public static final String NONDETERMINISTIC_TRANSITIONS = "arc.nondeterministic-transitions";
	/**
	 * A guard, action or variable initialiser does not type-check: a guard that is not Boolean, an
	 * operator on operands it does not apply to, a value of the wrong type assigned or sent, an
	 * expression that is not a call used as a statement. Members of Java types ({@code x.foo()}) are
	 * not known to the models and are checked by the Java compiler.
	 */
	public static final String EXPRESSION_TYPE = "arc.expression-type";
	/** An action assigns to an incoming port: only outgoing ports can be sent on. */
	public static final String SEND_ON_INPUT = "arc.send-on-input";
	/** An action assigns to a configuration parameter, which is fixed when the component is created. */
	public static final String NOT_ASSIGNABLE = "arc.not-assignable";
	/**
	 * A guard or action reads a port that carries no message there: an outgoing port, or an incoming
	 * port other than the transition's trigger (a variable initialiser reads no port at all).
	 */
	public static final String PORT_NOT_READABLE = "arc.port-not-readable";
	/** A component with subcomponents also has an automaton: its behaviour is its parts'. */
	public static final String AUTOMATON_IN_COMPOSED = "arc.automaton-in-composed";
	/** A subcomponent of a generic component type gets a different number of type arguments than the type has type parameters. */
	public static final String TYPE_ARGUMENT_COUNT = "arc.type-argument-count";
	/** A type argument is a primitive type ({@code Buffer<int>}); Java's generics take reference types ({@code Buffer<Integer>}). */
	public static final String PRIMITIVE_TYPE_ARGUMENT = "arc.primitive-type-argument";

	/** A component extends itself, directly or through its parents (MontiArc's CircularInheritance, 0xC1100). */
	public static final String INHERITANCE_CYCLE = "arc.inheritance-cycle";
	/** {@code <<delayed>>} on an incoming port: only an outgoing port can hold its messages back (MontiArc's DelayOutPortOnly, 0xC1116). */
	public static final String DELAYED_IN_PORT = "arc.delayed-in-port";
	/** A port or automaton has two timings ({@code <<sync, timed>>}; MontiArc's OnlyOneTiming, 0xC1114). */
	public static final String MULTIPLE_TIMINGS = "arc.multiple-timings";
	/**
	 * Subcomponents send to each other in a loop and no port on it is {@code <<delayed>>}: within one time
	 * slice each would wait for the others (MontiArc's FeedbackStrongCausality, 0xC1117).
	 */
	public static final String FEEDBACK_WITHOUT_DELAY = "arc.feedback-without-delay";
	/** A configuration parameter without a default value follows one with (MontiArc's OptionalConfigurationParametersLast, 0xC1126). */
	public static final String OPTIONAL_PARAMETER_ORDER = "arc.optional-parameter-order";
	/** A type argument is not within its type parameter's upper bound ({@code Sum<Boolean>} for {@code Sum<T extends Number>}; MontiArc's SubcomponentTypeBound, 0xC1202). */
	public static final String TYPE_BOUND = "arc.type-bound";
}
