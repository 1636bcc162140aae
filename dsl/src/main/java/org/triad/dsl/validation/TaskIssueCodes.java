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

	/** {@code if}, {@code while} or {@code else} in a task: tasks have no conditions or loops by design. */
	public static final String NO_CONDITION = "task.no-condition";
	/** {@code forall} in a task: tasks list their goals one by one. */
	public static final String NO_LOOP = "task.no-loop";
	/** {@code priority} in a task: a priority is given when the task is submitted. */
	public static final String NO_PRIORITY = "task.no-priority";
	/** {@code before 08:00} or {@code after ...} on a task or goal reference: when a task runs is decided when it is submitted. */
	public static final String NO_TIME = "task.no-time";
}
