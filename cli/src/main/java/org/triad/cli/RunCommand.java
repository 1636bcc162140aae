package org.triad.cli;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.Callable;

import org.triad.refarc.RefArcRun;
import org.triad.refarc.RefArcRunner;
import org.triad.refarc.Status;
import org.triad.refarc.model.DryRunWorld;
import org.triad.refarc.model.SchemaGoalPlanner;
import org.triad.runtime.app.State;
import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;
import org.triad.runtime.schema.ModelPlanner;
import org.triad.runtime.schema.ModelTask;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad run DIR --state S.state --task "Fetch(gauze, storage, ward3)"}: a dry run through RefArc. */
@Command(name = "run", mixinStandardHelpOptions = true,
		description = { "Execute a task through the reference architecture RefArc against a situation, with a robot and a world",
				"whose actions do exactly what their postconditions say. Prints the Status stream.",
				"Exit code: 0 when the task completed, 1 when it was aborted, 2 for bad input." })
public final class RunCommand implements Callable<Integer> {
	@CommandLine.Mixin
	private SituationOptions app;

	@Option(names = "--task", required = true, paramLabel = "TASK(args)", description = "the task, e.g. \"Fetch(gauze, storage, ward3)\"")
	private String task;

	@Option(names = "--fail", paramLabel = "ACTION[@N]", description = "make the N-th call (default: first) of ACTION fail; repeatable")
	private List<String> failures = List.of();

	@Option(names = "--planner", paramLabel = "triad|pddl4j|COMMAND",
			description = "the planner: triad (default), pddl4j, or an external planner's command line with {domain} {problem} [{plan}];"
					+ " default from $TRIAD_PLANNER")
	private String planner = System.getenv(PddlPlanners.ENV);

	@Option(names = "--planning-timeout", paramLabel = "SECONDS", description = "time limit of one planning call (default 30)")
	private double planningTimeout = 30;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		SituationOptions.Opened opened = app.open();
		ModelSession session = opened.session();
		State s = opened.state();
		ModelSession.Call call = ModelSession.parseCall(task, s);
		ModelTask instance = new ModelTask(session.schema, call.name(), call.args());
		DryRunWorld world = new DryRunWorld(session.schema, s);
		for (String f : failures) {
			String[] parts = f.split("@", 2);
			int nth;
			try {
				nth = parts.length == 2 ? Integer.parseInt(parts[1]) : 1;
			} catch (NumberFormatException e) {
				throw new ModelSession.UserError("--fail takes ACTION or ACTION@N with N a number, not '" + f + "'");
			}
			if (session.schema.actions().stream().noneMatch(a -> a.name().equals(parts[0]))) {
				throw new ModelSession.UserError("--fail: the application has no action '" + parts[0] + "'");
			}
			world.failOnCall(parts[0], nth);
		}
		PddlPlanner engine;
		try {
			engine = PddlPlanners.byName(planner);
		} catch (IllegalArgumentException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
		ModelPlanner modelPlanner = new ModelPlanner(session.schema, engine, Duration.ofMillis((long) (planningTimeout * 1000)));
		RefArcRun run = new RefArcRunner(world, new SchemaGoalPlanner(modelPlanner), world).run(instance);
		for (Status status : run.statuses()) {
			spec.commandLine().getOut().println(status);
		}
		return run.outcome() == RefArcRun.Outcome.COMPLETED ? 0 : 1;
	}
}
