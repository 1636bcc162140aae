package org.triad.dsl.validation;

/** Stable codes of diagnostics of tasks ({@code .task}). */
public final class TaskIssueCodes {
	private TaskIssueCodes() {
	}

	/** A goal reference with the wrong number of arguments. */
	public static final String ARGUMENT_COUNT = "task.argument-count";
	/** A goal reference argument whose type does not fit the goal's parameter. */
	public static final String ARGUMENT_TYPE = "task.argument-type";
	/** A goal reference argument that is neither a task parameter nor a literal. */
	public static final String ARGUMENT_KIND = "task.argument-kind";
	/** A task without goals (warning). */
	public static final String EMPTY = "task.empty";
	/** A task parameter no goal reference uses (warning). */
	public static final String UNUSED_PARAMETER = "task.unused-parameter";
}
