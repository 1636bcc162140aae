package org.triad.runtime.schema;

import java.util.List;

/** A goal: parameters and the situation that must hold. */
public record GoalSchema(String name, List<Param> params, Expr condition) {
	public GoalSchema {
		params = List.copyOf(params);
	}
}
