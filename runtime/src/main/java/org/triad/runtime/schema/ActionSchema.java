package org.triad.runtime.schema;

import java.util.List;

/** An action of an actor: parameters, a precondition and the effects of its postcondition. */
public record ActionSchema(String actor, String name, List<Param> params, Expr pre, List<Effect> effects) {
	public ActionSchema {
		params = List.copyOf(params);
		effects = List.copyOf(effects);
	}
}
