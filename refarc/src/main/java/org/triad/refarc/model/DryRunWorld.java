package org.triad.refarc.model;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Transitions;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;

/**
 * A robot and a world whose actions do exactly what their postconditions say, over a state: for
 * dry runs of tasks without a robot or a simulator. Failures can be injected: the n-th call of an
 * action fails (returns false and changes nothing).
 */
public final class DryRunWorld implements StateSource, ActionRunner {
	private final Transitions transitions;
	private final Map<String, Integer> calls = new HashMap<>();
	private final Map<String, Set<Integer>> failAt = new HashMap<>();
	private State state;

	public DryRunWorld(AppSchema schema, State initial) {
		this.transitions = new Transitions(schema);
		this.state = initial;
	}

	/** Makes the {@code nth} (1-based) call of the action with this name fail, in addition to those already set. */
	public DryRunWorld failOnCall(String action, int nth) {
		if (nth < 1) {
			throw new IllegalArgumentException("calls are counted from 1, not " + nth);
		}
		failAt.computeIfAbsent(action, a -> new HashSet<>()).add(nth);
		return this;
	}

	@Override
	public synchronized State currentState() {
		return state;
	}

	@Override
	public Optional<String> violatedPrecondition(GroundAction a, State now) {
		return transitions.violatedPrecondition(a, now);
	}

	@Override
	public synchronized boolean execute(GroundAction a) {
		int n = calls.merge(a.action(), 1, Integer::sum);
		if (failAt.getOrDefault(a.action(), Set.of()).contains(n)) {
			return false;
		}
		state = transitions.apply(a, state);
		return true;
	}
}
