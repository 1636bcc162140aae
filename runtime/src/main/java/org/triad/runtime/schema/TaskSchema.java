package org.triad.runtime.schema;

import java.util.List;

/** A task: parameters and the goals to satisfy in order, each with argument expressions over the task's parameters. */
public record TaskSchema(String name, List<Param> params, List<Step> steps) {
	public TaskSchema {
		params = List.copyOf(params);
		steps = List.copyOf(steps);
	}

	/** A goal reference of a task. */
	public record Step(String goal, List<Expr> args) {
		public Step {
			args = List.copyOf(args);
		}
	}
}
