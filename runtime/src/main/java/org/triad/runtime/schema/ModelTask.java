package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;

/** A task instance read from the schema: its arguments substituted into its goal references. */
public final class ModelTask implements TaskInstance {
	private final TaskSchema task;
	private final List<Object> args;
	private final List<GoalInstance> goals;

	public ModelTask(AppSchema schema, String taskName, List<Object> args) {
		this.task = schema.task(taskName).orElseThrow(() -> new ModelEvaluationException("unknown task '" + taskName + "'"));
		if (task.params().size() != args.size()) {
			throw new ModelEvaluationException("task " + taskName + " takes " + task.params().size() + " argument(s), not " + args.size());
		}
		this.args = List.copyOf(args);
		Map<String, Object> binding = new LinkedHashMap<>();
		for (int i = 0; i < args.size(); i++) {
			binding.put(task.params().get(i).name(), args.get(i));
		}
		Evaluator evaluator = new Evaluator(schema);
		State empty = State.builder().build();
		List<GoalInstance> gs = new ArrayList<>();
		for (TaskSchema.Step step : task.steps()) {
			List<Object> values = new ArrayList<>();
			for (Expr a : step.args()) {
				values.add(evaluator.eval(a, empty, binding));
			}
			gs.add(new ModelGoal(schema, step.goal(), values));
		}
		this.goals = List.copyOf(gs);
	}

	@Override
	public String name() {
		return task.name();
	}

	@Override
	public List<Object> args() {
		return args;
	}

	@Override
	public List<GoalInstance> goals() {
		return goals;
	}
}
