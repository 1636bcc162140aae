package org.triad.runtime.schema;

import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.PddlStep;
import org.triad.planner.SolveResult;
import org.triad.planner.PddlPlanner;
import org.triad.planner.TriadEngine;

/**
 * Plans a goal of an application from a state: translates to PDDL, runs the configured planner,
 * reads the plan back into the application's actions. Failures are results with a reason, never
 * exceptions.
 */
public final class ModelPlanner {
	private final AppSchema schema;
	private final PddlTranslator translator;
	private final PddlPlanner planner;
	private final Duration timeout;

	public ModelPlanner(AppSchema schema) {
		this(schema, new TriadEngine(), Duration.ofSeconds(30));
	}

	public ModelPlanner(AppSchema schema, PddlPlanner planner, Duration timeout) {
		this.schema = schema;
		this.translator = new PddlTranslator(schema);
		this.planner = planner;
		this.timeout = timeout;
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
			SolveResult result = planner.solve(PddlParser.parseDomain(task.domain(), "domain.pddl"),
					PddlParser.parseProblem(task.problem(), "problem.pddl"), timeout);
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
