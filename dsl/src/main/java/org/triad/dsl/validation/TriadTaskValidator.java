package org.triad.dsl.validation;

import java.util.List;

import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.validation.Check;
import org.triad.dsl.semantics.Postconditions;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.GoalReference;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Task;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

/** Rules of tasks; codes in {@link TaskIssueCodes}. */
public class TriadTaskValidator extends AbstractTriadTaskValidator {

	@Check
	public void checkGoalReference(GoalReference ref) {
		Goal goal = ref.getGoal();
		for (int i = 0; i < ref.getArguments().size(); i++) {
			Expression arg = ref.getArguments().get(i);
			if (!Postconditions.isValue(arg)) {
				error("argument " + (i + 1) + " of '" + (goal == null || goal.eIsProxy() ? "?" : goal.getName())
						+ "' must be a task parameter or a literal", ref, P.getGoalReference_Arguments(), i, TaskIssueCodes.ARGUMENT_KIND);
			}
		}
		if (goal == null || goal.eIsProxy()) {
			return;
		}
		List<Parameter> params = goal.getParameters();
		if (params.size() != ref.getArguments().size()) {
			error("goal '" + goal.getName() + "' takes " + params.size() + " argument(s), but " + ref.getArguments().size() + " are given",
					ref, P.getGoalReference_Goal(), TaskIssueCodes.ARGUMENT_COUNT);
			return;
		}
		for (int i = 0; i < params.size(); i++) {
			TriadType expected = TriadTypeSystem.typeOf(params.get(i).getType());
			TriadType actual = TriadTypeSystem.typeOf(ref.getArguments().get(i));
			if (!TriadTypeSystem.isAssignable(expected, actual)) {
				error("argument " + (i + 1) + " of goal '" + goal.getName() + "' must be " + expected.displayAgainst(actual) + ", but is "
						+ actual.displayAgainst(expected), ref, P.getGoalReference_Arguments(), i, TaskIssueCodes.ARGUMENT_TYPE);
			}
		}
	}

	@Check
	public void checkTask(Task task) {
		if (task.getSteps().isEmpty()) {
			warning("task '" + task.getName() + "' has no goals", task, P.getNamedElement_Name(), TaskIssueCodes.EMPTY);
		}
		for (Parameter p : task.getParameters()) {
			if (isDuplicate(p)) {
				continue; // reported as a duplicate; references resolve to the first one
			}
			boolean used = EcoreUtil2.getAllContentsOfType(task, ValueRef.class).stream().anyMatch(r -> r.getValue() == p);
			if (!used) {
				warning("parameter '" + p.getName() + "' of task '" + task.getName() + "' is not used", p, P.getNamedElement_Name(),
						TaskIssueCodes.UNUSED_PARAMETER);
			}
		}
	}
}
