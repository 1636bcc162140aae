package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.List;

import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.Problem;

/**
 * A task with its numbers left out: every comparison of numbers holds (negated or not), numeric effects and
 * costs are dropped. Every plan of the task is one of this relaxation, so a goal this one cannot reach the task
 * cannot reach either, and the classical search says which facts are missing (the numeric search only says that
 * nothing reaches the goal). {@link GoalSolver} asks it why when a goal of an application with quantities (a
 * battery drained by moves) is unreachable for another reason than its numbers.
 */
final class FactsOnly {
	private FactsOnly() {
	}

	static Domain domain(Domain d) {
		List<Action> actions = new ArrayList<>();
		for (Action a : d.actions()) {
			actions.add(new Action(a.name(), a.parameters(), formula(a.precondition()), effects(a.effects())));
		}
		List<String> requirements = d.requirements().stream()
				.filter(r -> !r.equals(":fluents") && !r.equals(":numeric-fluents") && !r.equals(":action-costs")).toList();
		return new Domain(d.name(), requirements, d.types(), d.constants(), d.predicates(), List.of(), actions, d.axioms());
	}

	static Problem problem(Problem p) {
		return new Problem(p.name(), p.domainName(), p.objects(), p.init(), List.of(), formula(p.goal()), null);
	}

	private static Formula formula(Formula f) {
		return relaxed(f, true);
	}

	/**
	 * {@code f} with each comparison of numbers made to hold where it stands: true where it is asserted, false
	 * under a negation (or as the condition of an implication), so that the formula only ever gets weaker.
	 */
	private static Formula relaxed(Formula f, boolean positive) {
		if (f == null) {
			return null;
		}
		if (f instanceof Formula.Compare) {
			return positive ? new Formula.And(List.of()) : new Formula.Or(List.of());
		}
		if (f instanceof Formula.Not n) {
			return new Formula.Not(relaxed(n.body(), !positive));
		}
		if (f instanceof Formula.And a) {
			return new Formula.And(a.parts().stream().map(x -> relaxed(x, positive)).toList());
		}
		if (f instanceof Formula.Or o) {
			return new Formula.Or(o.parts().stream().map(x -> relaxed(x, positive)).toList());
		}
		if (f instanceof Formula.Imply i) {
			return new Formula.Imply(relaxed(i.condition(), !positive), relaxed(i.consequence(), positive));
		}
		if (f instanceof Formula.Forall a) {
			return new Formula.Forall(a.variables(), relaxed(a.body(), positive));
		}
		if (f instanceof Formula.Exists e) {
			return new Formula.Exists(e.variables(), relaxed(e.body(), positive));
		}
		return f;
	}

	private static List<PddlEffect> effects(List<PddlEffect> effects) {
		List<PddlEffect> kept = new ArrayList<>();
		for (PddlEffect e : effects) {
			if (e instanceof PddlEffect.Forall a) {
				kept.add(new PddlEffect.Forall(a.variables(), effects(a.body())));
			} else if (e instanceof PddlEffect.When w) {
				// the condition relaxed as a precondition is (what can be reached only grows: reachability ignores deletes)
				kept.add(new PddlEffect.When(formula(w.condition()), effects(w.body())));
			} else if (e instanceof PddlEffect.Add || e instanceof PddlEffect.Delete) {
				kept.add(e);
			}
			// numeric effects and costs: left out
		}
		return kept;
	}
}
