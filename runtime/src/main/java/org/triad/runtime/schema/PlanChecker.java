package org.triad.runtime.schema;

import java.util.Map;
import java.util.Optional;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;

/**
 * Replays a plan against a state with the actions' pre- and postconditions, as a plan validator
 * does: every precondition must hold when its action is reached, and the goal at the end.
 */
public final class PlanChecker {
	private final Transitions transitions;

	public PlanChecker(AppSchema schema) {
		this.transitions = new Transitions(schema);
	}

	/** The outcome of a replay: the state reached, and the first problem if any (step is 0-based, -1 for the goal). */
	public record Verdict(boolean valid, int failedStep, String reason, State finalState) {
		public Optional<String> refutation() {
			return valid ? Optional.empty() : Optional.of(reason);
		}
	}

	public Verdict check(State initial, Plan plan, GoalInstance goal) {
		State s = initial;
		for (int i = 0; i < plan.size(); i++) {
			GroundAction a = plan.actions().get(i);
			try {
				if (!transitions.isApplicable(a, s)) {
					return new Verdict(false, i, "step " + (i + 1) + " " + a + ": precondition "
							+ Exprs.show(transitions.schemaOf(a).pre()) + " does not hold", s);
				}
				s = transitions.apply(a, s);
			} catch (ModelEvaluationException e) {
				return new Verdict(false, i, "step " + (i + 1) + " " + a + ": " + e.getMessage(), s);
			}
		}
		if (goal != null && !goal.isSatisfiedIn(s)) {
			return new Verdict(false, -1, "after the plan, goal " + goal.describe() + " does not hold", s);
		}
		return new Verdict(true, -2, "", s);
	}

	/** Checks against a goal given by its schema and arguments. */
	public Verdict check(State initial, Plan plan, GoalSchema goal, Map<String, Object> binding) {
		Evaluator ev = transitions.evaluator();
		return check(initial, plan, new GoalInstance() {
			@Override
			public String name() {
				return goal.name();
			}

			@Override
			public java.util.List<Object> args() {
				return java.util.List.copyOf(binding.values());
			}

			@Override
			public boolean isSatisfiedIn(State state) {
				return ev.holds(goal.condition(), state, binding);
			}
		});
	}
}
