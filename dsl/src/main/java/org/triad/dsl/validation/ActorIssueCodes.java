package org.triad.dsl.validation;

/** Stable codes of diagnostics of robot and world actors ({@code .actor}). */
public final class ActorIssueCodes {
	private ActorIssueCodes() {
	}

	/** Two properties or actions of one actor with the same name. */
	public static final String DUPLICATE_MEMBER = "actor.duplicate-member";
	/** A postcondition that is not a conjunction ({@code &&}) of effects. */
	public static final String POST_NOT_EFFECT = "actor.post-not-effect";
	/** An effect {@code f(args) == v} whose value is not a parameter, literal or enum literal, or does not fit f's type. */
	public static final String EFFECT_VALUE = "actor.effect-value";
	/** One postcondition that sets the same property twice, or both makes it hold and not hold. */
	public static final String CONFLICTING_EFFECTS = "actor.conflicting-effects";
	/** A property read in the value of an effect without {@code @pre}: after the action it would be the value being set. */
	public static final String EFFECT_NEEDS_PRE = "actor.effect-needs-pre";
	/** An action's {@code cost:} that is not a number. */
	public static final String COST_NOT_NUMERIC = "actor.cost-not-numeric";
	/** A second robot or a second world in one application. */
	public static final String DUPLICATE_KIND = "actor.duplicate-kind";
}
