package org.triad.runtime.schema;

import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.planner.PddlStep;
import org.triad.planner.SolveResult;
import org.triad.planner.PddlPlanner;
import org.triad.planner.TriadEngine;

/**
 * Solves a goal of an application from a state: the bridge from goals to PDDL to plans. Translates
 * the goal to the planner's typed PDDL model ({@link PddlTranslator}), runs the configured
 * {@link PddlPlanner}, reads the plan back into the application's actions. Failures are results with
 * a reason, never exceptions. (RefArc's Planner component plans through it, see
 * {@code refarc.model.SchemaGoalPlanner}.)
 */
public final class GoalSolver {
	private final AppSchema schema;
	private final PddlTranslator translator;
	private final PddlPlanner planner;
	private final Duration timeout;
	/** Extra costs of actions (congestion), or null for the shortest plan. */
	private final ActionCosts costs;

	public GoalSolver(AppSchema schema) {
		this(schema, new TriadEngine(), Duration.ofSeconds(30));
	}

	public GoalSolver(AppSchema schema, PddlPlanner planner, Duration timeout) {
		this(schema, planner, timeout, null);
	}

	private GoalSolver(AppSchema schema, PddlPlanner planner, Duration timeout, ActionCosts costs) {
		this.schema = schema;
		this.translator = new PddlTranslator(schema);
		this.planner = planner;
		this.timeout = timeout;
		this.costs = costs;
	}

	/**
	 * This solver asking for the plan of least cost, every action costing {@code 1 + costs.extra(action)}
	 * (the congestion hook: a move's expected wait), instead of the shortest plan.
	 */
	public GoalSolver withCosts(ActionCosts costs) {
		return new GoalSolver(schema, planner, timeout, java.util.Objects.requireNonNull(costs, "costs"));
	}

	/** A plan, or the reason there is none. */
	public record Outcome(Plan plan, String failure) {
		public boolean planned() {
			return plan != null;
		}
	}

	public Outcome plan(String goal, List<Object> args, State from) {
		try {
			ModelGoal g = new ModelGoal(schema, goal, args);
			return plan(g.schema(), g.binding(), from);
		} catch (ModelEvaluationException | PddlTranslationException e) {
			return new Outcome(null, e.getMessage());
		}
	}

	public Outcome plan(GoalSchema goal, Map<String, Object> binding, State from) {
		try {
			PddlTranslator.Task task = translator.translate(from, goal, binding);
			SolveResult result;
			if (costs == null) {
				result = planner.solve(task.domain(), task.problem(), timeout);
			} else {
				ActionCosts.Costed costed = ActionCosts.apply(task, costs);
				result = planner.solve(costed.domain(), costed.problem(), timeout);
			}
			if (!result.unreachable().isEmpty()) {
				return new Outcome(null, "no plan: " + new UnreachableGoalText(schema, task.names())
						.describe(UnreachableGoalText.goalLabel(goal, binding), result.unreachable()));
			}
			if (!result.isSolved()) {
				return new Outcome(null, switch (result.status()) {
					case UNSOLVABLE -> "no plan: " + (result.message().isEmpty() ? "the goal is unreachable" : result.message());
					case TIMEOUT -> "no plan within " + timeout.toMillis() + " ms";
					default -> "planner error: " + result.message();
				});
			}
			List<PddlStep> steps = result.plan().steps();
			return new Outcome(task.plan(steps.stream().map(PddlStep::name).toList(), steps.stream().map(PddlStep::args).toList()), null);
		} catch (PddlTranslationException | ModelEvaluationException e) {
			return new Outcome(null, e.getMessage());
		} catch (RuntimeException e) {
			return new Outcome(null, "planning failed: " + e);
		}
	}

	public PddlTranslator translator() {
		return translator;
	}
}
