package org.triad.dsl.validation;

/** Stable codes of diagnostics of class diagrams ({@code .cd}). */
public final class CdIssueCodes {
	private CdIssueCodes() {
	}

	public static final String DUPLICATE_TYPE = "cd.duplicate-type";
	public static final String CYCLIC_INHERITANCE = "cd.cyclic-inheritance";
	/** An attribute declared twice in a class or again in a subclass. */
	public static final String DUPLICATE_ATTRIBUTE = "cd.duplicate-attribute";
	public static final String DUPLICATE_LITERAL = "cd.duplicate-literal";
	/** An enumeration without literals (warning). */
	public static final String EMPTY_ENUM = "cd.empty-enum";
}
