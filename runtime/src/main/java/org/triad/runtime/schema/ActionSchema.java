package org.triad.runtime.schema;

import java.util.List;

/**
 * An action of an actor: parameters, a precondition, the effects of its postcondition, and its cost (what
 * one execution costs, e.g. the distance driven; null when the model states none, which plans as 1 step).
 */
public record ActionSchema(String actor, String name, List<Param> params, Expr pre, List<Effect> effects, Expr cost) {
	public ActionSchema {
		params = List.copyOf(params);
		effects = List.copyOf(effects);
	}

	/** An action without a stated cost. */
	public ActionSchema(String actor, String name, List<Param> params, Expr pre, List<Effect> effects) {
		this(actor, name, params, pre, effects, null);
	}
}
