package org.triad.runtime.schema;

import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.triad.planner.UnreachableGoal;
import org.triad.planner.pddl.Formula;

/**
 * Says why a goal is unreachable in the model's terms: the planner's explanation (PDDL atoms over
 * translated names) read back into properties and objects, e.g.
 * {@code Holds(gauze) unreachable: Courier.carries(gauze) needs Building.itemAt(gauze, _): none in the current state ...}.
 */
final class UnreachableGoalText {
	private final AppSchema schema;
	private final PddlNames names;

	UnreachableGoalText(AppSchema schema, PddlNames names) {
		this.schema = schema;
		this.names = names;
	}

	/** {@code goal} is the goal as the model names it, e.g. {@code Holds(gauze)}. */
	String describe(String goal, List<UnreachableGoal> unreachable) {
		return goal + " unreachable: " + unreachable.stream().map(this::describe).collect(Collectors.joining("; "));
	}

	private String describe(UnreachableGoal u) {
		StringBuilder sb = new StringBuilder(condition(u.goal()));
		for (Formula.Atom a : u.needs()) {
			sb.append(" needs ").append(condition(a));
		}
		String missing = u.missing().stream().map(this::condition).collect(Collectors.joining(" or "));
		if (u.kind() == UnreachableGoal.Kind.STATIC) {
			sb.append(": the actions that could reach it need ").append(missing).append(UnreachableGoal.anyNote(u.missing()))
					.append(", which the current state lacks");
		} else {
			sb.append(" needs ").append(missing).append(": none in the current state, and no action makes one from what can be reached");
		}
		return sb.toString();
	}

	/** {@code Actor.prop(args)} for a Boolean property, {@code Actor.prop(args) == value} otherwise. */
	private String condition(Formula.Atom atom) {
		if (atom.args().size() == 2 && (atom.predicate().equals(NumberOrder.LESS) || atom.predicate().equals(NumberOrder.AT_MOST))) {
			return value(atom.args().get(0)) + (atom.predicate().equals(NumberOrder.LESS) ? " < " : " <= ") + value(atom.args().get(1));
		}
		PropertySchema p = property(atom.predicate());
		if (p == null) {
			return atom.toString();
		}
		List<String> args = atom.args().stream().map(this::value).toList();
		int n = p.params().size();
		String call = p.actor() + "." + p.name() + "(" + String.join(", ", args.subList(0, Math.min(n, args.size()))) + ")";
		return p.isBoolean() || args.size() <= n ? call : call + " == " + args.get(n);
	}

	private PropertySchema property(String predicate) {
		for (PropertySchema p : schema.properties()) {
			if (PddlNames.predicate(p.actor(), p.name()).equals(predicate)) {
				return p;
			}
		}
		return null;
	}

	private String value(String pddlName) {
		if (UnreachableGoal.ANY.equals(pddlName)) {
			return pddlName;
		}
		Object v = names.valueOf(pddlName);
		return v == null ? pddlName : String.valueOf(v);
	}

	static String goalLabel(GoalSchema goal, Map<String, Object> binding) {
		return goal.name() + "(" + goal.params().stream().map(p -> String.valueOf(binding.get(p.name()))).collect(Collectors.joining(", ")) + ")";
	}
}
