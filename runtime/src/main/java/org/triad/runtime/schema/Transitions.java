package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * The meaning of actions as the models state it: an action applies when its precondition holds,
 * and its effects, all evaluated in the state before the action, give the state after it.
 */
public final class Transitions {
	private final AppSchema schema;
	private final Evaluator evaluator;

	public Transitions(AppSchema schema) {
		this.schema = schema;
		this.evaluator = new Evaluator(schema);
	}

	public ActionSchema schemaOf(GroundAction a) {
		ActionSchema s = schema.action(a.actor(), a.action())
				.orElseThrow(() -> new ModelEvaluationException("unknown action " + a.actor() + "." + a.action()));
		if (s.params().size() != a.args().size()) {
			throw new ModelEvaluationException(a + ": " + s.name() + " takes " + s.params().size() + " arguments");
		}
		return s;
	}

	public Map<String, Object> binding(ActionSchema s, GroundAction a) {
		Map<String, Object> binding = new LinkedHashMap<>();
		for (int i = 0; i < s.params().size(); i++) {
			binding.put(s.params().get(i).name(), a.args().get(i));
		}
		return binding;
	}

	/** Whether the action's precondition holds in the state. */
	public boolean isApplicable(GroundAction a, State state) {
		ActionSchema s = schemaOf(a);
		return evaluator.holds(s.pre(), state, binding(s, a));
	}

	/**
	 * Why the action cannot run in the state (its precondition, shown, or why it cannot be evaluated), or
	 * empty when it can: what an ActionExecutor reports before a robot would act on a stale plan.
	 */
	public Optional<String> violatedPrecondition(GroundAction a, State state) {
		try {
			return isApplicable(a, state) ? Optional.empty() : Optional.of("precondition " + Exprs.show(schemaOf(a).pre()) + " does not hold");
		} catch (ModelEvaluationException e) {
			return Optional.of(e.getMessage());
		}
	}

	/** The state after the action's effects; the precondition is not checked here. */
	public State apply(GroundAction a, State state) {
		ActionSchema s = schemaOf(a);
		Map<String, Object> binding = binding(s, a);
		List<Atom> atoms = new ArrayList<>();
		List<Object> values = new ArrayList<>();
		for (Effect e : s.effects()) {
			atoms.add(evaluator.atom(e.call(), state, binding));
			values.add(e.isAssignment() ? evaluator.eval(e.value(), state, binding) : e.holds());
		}
		State.Builder next = state.toBuilder();
		for (int i = 0; i < atoms.size(); i++) {
			next.value(atoms.get(i), values.get(i));
		}
		return next.build();
	}

	public Evaluator evaluator() {
		return evaluator;
	}
}
