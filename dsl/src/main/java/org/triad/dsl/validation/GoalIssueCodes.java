package org.triad.dsl.validation;

/** Stable codes of diagnostics of goals ({@code .goal}). */
public final class GoalIssueCodes {
	private GoalIssueCodes() {
	}

	/** A goal parameter its situation does not use (warning). */
	public static final String UNUSED_PARAMETER = "goal.unused-parameter";
	/** A goal situation that refers to no actor property, so no action can ever change it (warning). */
	public static final String NO_PROPERTY = "goal.no-property";

	/** {@code forall (T x)} or {@code exists (T x)} in a goal: goals have no quantifiers. */
	public static final String NO_QUANTIFIER = "goal.no-quantifier";
}
