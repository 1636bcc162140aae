package org.triad.generator.arc;

import java.util.ArrayList;
import java.util.List;

import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.Automaton;
import org.triad.dsl.arc.AutomatonState;
import org.triad.dsl.arc.Statement;
import org.triad.dsl.arc.Transition;
import org.triad.dsl.semantics.ArcModels;

/**
 * A hierarchical automaton as the flat one the generated code runs: it is always in a leaf state; a
 * transition of a super state applies in each of its leaves (after the leaf's own, inner first);
 * taking one runs the exit actions of the states it leaves (inner first), its own actions, then the
 * entry actions of the states it enters (outer first) and, into a super state, the initial actions
 * and entry actions down to the initial leaf.
 */
final class FlatAutomaton {
	private final Automaton automaton;

	FlatAutomaton(Automaton automaton) {
		this.automaton = automaton;
	}

	List<AutomatonState> leaves() {
		return ArcModels.leafStates(automaton);
	}

	/** The transitions that can fire in a leaf: its own, then its super states', in model order each. */
	List<Transition> candidates(AutomatonState leaf, ArcPort trigger, boolean anyTrigger) {
		List<Transition> all = ArcModels.allTransitions(automaton);
		List<Transition> result = new ArrayList<>();
		for (AutomatonState s : ArcModels.ancestry(leaf)) {
			for (Transition t : all) {
				if (t.getSource() == s && (anyTrigger || t.getTrigger() == trigger)) {
					result.add(t);
				}
			}
		}
		return result;
	}

	/** The statements run at start-up: the initial actions and entry actions down to the initial leaf. */
	List<Statement> startActions() {
		List<Statement> actions = new ArrayList<>();
		descend(ArcModels.initialState(automaton), actions);
		return actions;
	}

	AutomatonState initialLeaf() {
		return leafOf(ArcModels.initialState(automaton));
	}

	/** Exit, transition and entry actions of taking {@code t} in {@code leaf}, in order. */
	List<Statement> actions(AutomatonState leaf, Transition t) {
		List<AutomatonState> sourceChain = ArcModels.ancestry(t.getSource());
		List<AutomatonState> targetChain = ArcModels.ancestry(t.getTarget());
		AutomatonState scope = null;
		for (AutomatonState s : sourceChain) {
			if (s != t.getSource() && s != t.getTarget() && targetChain.contains(s)) {
				scope = s;
				break;
			}
		}
		List<Statement> actions = new ArrayList<>();
		for (AutomatonState s : ArcModels.ancestry(leaf)) {
			if (s == scope) {
				break;
			}
			actions.addAll(s.getExitActions());
		}
		actions.addAll(t.getActions());
		List<AutomatonState> entered = new ArrayList<>();
		for (AutomatonState s : targetChain) {
			if (s == scope) {
				break;
			}
			entered.add(0, s);
		}
		for (AutomatonState s : entered) {
			actions.addAll(s.getEntryActions());
		}
		AutomatonState initial = ArcModels.initialState(t.getTarget().getStates());
		if (initial != null) {
			descend(initial, actions);
		}
		return actions;
	}

	/** The leaf the transition ends in: its target, or the target's initial leaf. */
	AutomatonState targetLeaf(Transition t) {
		return leafOf(t.getTarget());
	}

	private static AutomatonState leafOf(AutomatonState s) {
		AutomatonState leaf = s;
		while (leaf != null && !leaf.getStates().isEmpty()) {
			leaf = ArcModels.initialState(leaf.getStates());
		}
		return leaf;
	}

	private static void descend(AutomatonState s, List<Statement> actions) {
		for (AutomatonState t = s; t != null; t = ArcModels.initialState(t.getStates())) {
			actions.addAll(t.getInitialActions());
			actions.addAll(t.getEntryActions());
			if (t.getStates().isEmpty()) {
				break;
			}
		}
	}
}
