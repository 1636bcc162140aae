package org.triad.runtime.schema;

import java.util.List;

/** A property of an actor: a relation when its type is boolean, a function of its arguments otherwise. */
public record PropertySchema(String actor, String name, List<Param> params, String type) {
	public PropertySchema {
		params = List.copyOf(params);
	}

	public boolean isBoolean() {
		return "boolean".equals(type);
	}
}
