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
}
