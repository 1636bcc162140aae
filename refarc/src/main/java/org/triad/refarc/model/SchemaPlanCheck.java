package org.triad.refarc.model;

import java.util.Optional;

import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.PlanChecker;
import org.triad.refarc.PlanCheck;

/** The plan verifier's check for any application: replay the plan with the models' pre- and postconditions. */
public final class SchemaPlanCheck implements PlanCheck {
	private final PlanChecker checker;

	public SchemaPlanCheck(AppSchema schema) {
		this.checker = new PlanChecker(schema);
	}

	@Override
	public Optional<String> refute(GoalInstance goal, State from, Plan plan) {
		return checker.check(from, plan, goal).refutation();
	}
}
