package org.triad.runtime.schema;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;

/** A goal instance read from the schema: its situation evaluated with the runtime evaluator. */
public final class ModelGoal implements GoalInstance {
	private final AppSchema schema;
	private final GoalSchema goal;
	private final List<Object> args;

	public ModelGoal(AppSchema schema, String goalName, List<Object> args) {
		this.schema = schema;
		this.goal = schema.goal(goalName).orElseThrow(() -> new ModelEvaluationException("unknown goal '" + goalName + "'"));
		if (goal.params().size() != args.size()) {
			throw new ModelEvaluationException("goal " + goalName + " takes " + goal.params().size() + " argument(s), not " + args.size());
		}
		this.args = List.copyOf(args);
	}

	public GoalSchema schema() {
		return goal;
	}

	/** The goal's parameters bound to its arguments. */
	public Map<String, Object> binding() {
		Map<String, Object> b = new LinkedHashMap<>();
		for (int i = 0; i < args.size(); i++) {
			b.put(goal.params().get(i).name(), args.get(i));
		}
		return b;
	}

	@Override
	public String name() {
		return goal.name();
	}

	@Override
	public List<Object> args() {
		return args;
	}

	@Override
	public boolean isSatisfiedIn(State state) {
		return new Evaluator(schema).holds(goal.condition(), state, binding());
	}
}
