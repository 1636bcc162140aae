package org.triad.dsl.validation;

import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.validation.Check;
import org.triad.dsl.triad.UnsupportedConstruct;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.ValueRef;

/** Rules of goals; codes in {@link GoalIssueCodes} and {@link CommonIssueCodes}. */
public class TriadGoalValidator extends AbstractTriadGoalValidator {

	@Check
	public void checkCondition(Goal goal) {
		requireCondition(goal.getCondition(), "the situation of goal '" + goal.getName() + "'", goal, P.getGoal_Condition());
		if (goal.getCondition() != null && EcoreUtil2.getAllContentsOfType(goal.getCondition(), PropertyCall.class).isEmpty()
				&& !(goal.getCondition() instanceof PropertyCall)) {
			warning("goal '" + goal.getName() + "' refers to no property of an actor, so no action can achieve or change it", goal,
					P.getNamedElement_Name(), GoalIssueCodes.NO_PROPERTY);
		}
	}

	@Check
	public void checkParametersUsed(Goal goal) {
		for (Parameter p : goal.getParameters()) {
			if (isDuplicate(p)) {
				continue; // reported as a duplicate; references resolve to the first one
			}
			boolean used = EcoreUtil2.getAllContentsOfType(goal, ValueRef.class).stream().anyMatch(r -> r.getValue() == p)
					|| EcoreUtil2.getAllContentsOfType(goal, org.triad.dsl.triad.MemberRef.class).stream().anyMatch(r -> r.getOwner() == p);
			if (!used) {
				warning("parameter '" + p.getName() + "' of goal '" + goal.getName() + "' is not used", p, P.getNamedElement_Name(),
						GoalIssueCodes.UNUSED_PARAMETER);
			}
		}
	}

	/** {@code forall (T x)} before a goal's condition: one finding on the keyword, saying what to write instead. */
	@Check
	public void checkUnsupported(UnsupportedConstruct c) {
		if ("forall".equals(c.getKeyword()) || "exists".equals(c.getKeyword())) {
			error("goals have no '" + c.getKeyword() + "': a goal is a condition over named objects; write it for each object"
					+ " (Building.itemAt(gauze, ward1) && Building.itemAt(mask, ward1)) or give the goal a parameter and reference it once per"
					+ " object in a task", c, P.getUnsupportedConstruct_Keyword(), GoalIssueCodes.NO_QUANTIFIER);
		}
	}
}
