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
import org.triad.dsl.triad.UnsupportedConstruct;
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
		if (task.getSteps().isEmpty() && task.getUnsupported().isEmpty()) { // a task made of an 'if' has its own finding
			warning("task '" + task.getName() + "' has no goals", task, P.getNamedElement_Name(), TaskIssueCodes.EMPTY);
		}
		for (Parameter p : task.getParameters()) {
			if (isDuplicate(p)) {
				continue; // reported as a duplicate; references resolve to the first one
			}
			boolean used = EcoreUtil2.getAllContentsOfType(task, ValueRef.class).stream().anyMatch(r -> r.getValue() == p)
					|| EcoreUtil2.getAllContentsOfType(task, org.triad.dsl.triad.MemberRef.class).stream().anyMatch(r -> r.getOwner() == p);
			if (!used) {
				warning("parameter '" + p.getName() + "' of task '" + task.getName() + "' is not used", p, P.getNamedElement_Name(),
						TaskIssueCodes.UNUSED_PARAMETER);
			}
		}
	}

	/** One finding per construct tasks do not have, on its keyword, saying what to write instead. */
	@Check
	public void checkUnsupported(UnsupportedConstruct c) {
		String keyword = c.getKeyword();
		if (keyword == null) {
			return;
		}
		switch (keyword) {
		case "if", "while", "else" -> error("tasks have no '" + keyword + "' by design (a task is a fixed sequence of goals): write one task per case,"
				+ " e.g. 'FetchAndDeliver' and 'Deliver', and let whoever submits the task choose; a goal that already holds is skipped,"
				+ " so a step that may be done already needs no condition", c, P.getUnsupportedConstruct_Keyword(), TaskIssueCodes.NO_CONDITION);
		case "forall" -> error("tasks have no 'forall': list the goals one by one (IsAt(ward1); IsAt(ward2);), or give the task one parameter"
				+ " per object", c, P.getUnsupportedConstruct_Keyword(), TaskIssueCodes.NO_LOOP);
		case "priority" -> error("a task has no priority in its model: the priority is given when the task is submitted (the service's task API),"
				+ " so one task serves urgent and routine requests", c, P.getUnsupportedConstruct_Keyword(), TaskIssueCodes.NO_PRIORITY);
		case "before", "after" -> error("tasks and goals have no time ('" + keyword + " " + c.getValue() + "'): when a task runs is decided when it is"
				+ " submitted (submit it at the right time); a deadline is not planned for", c, P.getUnsupportedConstruct_Keyword(), TaskIssueCodes.NO_TIME);
		default -> {
			// quantifiers belong to goals; TriadGoalValidator reports them
		}
		}
	}
}
