package org.triad.refarc.model;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.GoalSolver;
import org.triad.refarc.GoalPlanner;
import org.triad.refarc.PlanningOutcome;

/** The Planner behaviour for any application: its schema translated to PDDL and planned at runtime. */
public final class SchemaGoalPlanner implements GoalPlanner {
	private final GoalSolver planner;

	public SchemaGoalPlanner(GoalSolver planner) {
		this.planner = planner;
	}

	@Override
	public PlanningOutcome plan(GoalInstance goal, State from) {
		return outcome(planner.plan(goal.name(), goal.args(), from));
	}

	/** The goal planned with the rest of its task as a lookahead ({@link GoalSolver#plan(GoalInstance, java.util.List, State)}). */
	@Override
	public PlanningOutcome plan(GoalInstance goal, java.util.List<GoalInstance> then, State from) {
		return outcome(planner.plan(goal, then, from));
	}

	private static PlanningOutcome outcome(GoalSolver.Outcome outcome) {
		if (outcome.planned()) {
			return PlanningOutcome.planned(outcome.plan());
		}
		return outcome.proven() ? PlanningOutcome.unsolvable(outcome.failure()) : PlanningOutcome.failed(outcome.failure());
	}
}
