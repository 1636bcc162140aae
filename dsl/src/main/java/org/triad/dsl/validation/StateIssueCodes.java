package org.triad.dsl.validation;

/** Stable codes of diagnostics of situations ({@code .state}). */
public final class StateIssueCodes {
	private StateIssueCodes() {
	}

	/** Two objects of one situation with the same name. */
	public static final String DUPLICATE_OBJECT = "state.duplicate-object";
	/** An object of an abstract class. */
	public static final String ABSTRACT_OBJECT = "state.abstract-object";
	/** A fact that is neither {@code A.p(args)} for a Boolean property nor {@code A.f(args) == v}. */
	public static final String FACT_KIND = "state.fact-kind";
	/** A fact argument or value that is not an object of the situation or a literal. */
	public static final String FACT_ARGUMENT = "state.fact-argument";
	/** A property given two different values for the same arguments. */
	public static final String CONFLICTING_VALUE = "state.conflicting-value";
	/** An attribute given a value twice. */
	public static final String DUPLICATE_ATTRIBUTE = "state.duplicate-attribute";
	/** An attribute value that is not a literal of the attribute's type. */
	public static final String ATTRIBUTE_VALUE = "state.attribute-value";
	/** A situation that extends itself, directly or through others ({@code state A extends B}, {@code state B extends A}). */
	public static final String EXTENDS_CYCLE = "state.extends-cycle";
	/**
	 * A quantity without arguments that a situation (with the ones it extends) gives no value, or an object
	 * without a value for an attribute the models compute with: every action that reads it could never apply.
	 */
	public static final String UNDEFINED_QUANTITY = "state.undefined-quantity";
}
