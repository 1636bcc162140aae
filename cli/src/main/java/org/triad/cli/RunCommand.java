package org.triad.cli;

import java.io.PrintWriter;
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
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.ModelTask;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.ModelAgvActors;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.VdaTimeouts;
import org.triad.vda5050.mqtt.BrokerUnreachableException;

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

	@Option(names = "--robots", paramLabel = "vda5050:tcp://HOST:PORT",
			description = "execute the actions on a VDA 5050 robot on this MQTT broker instead of the dry run"
					+ " (an action with src and dst drives that edge, any other is a node action; see vda5050/README.md)")
	private String robots;

	@Option(names = "--serial", paramLabel = "SERIAL", description = "the VDA 5050 robot's serial number, with --robots (default: ${DEFAULT-VALUE})")
	private String serial = "courier-1";

	@CommandLine.Mixin
	private MqttCredentialsOption credentials = new MqttCredentialsOption();

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		// configuration errors are refused before anything runs, not found out as failures at runtime
		if (!(planningTimeout > 0) || Double.isInfinite(planningTimeout)) {
			throw new ModelSession.UserError("--planning-timeout takes a time in seconds > 0, not " + planningTimeout);
		}
		PlannerOption.resolve(planner); // an unknown planner or a missing program is refused here, before anything runs
		SituationOptions.Opened opened = app.open();
		ModelSession session = opened.session();
		State s = opened.state();
		ModelSession.Call call = ModelSession.parseCall(task, s);
		TaskArgumentCheck.check(session.schema, call.name(), call.args());
		ModelTask instance = new ModelTask(session.schema, call.name(), call.args());
		if (robots != null) {
			return runOnRobot(session, s, instance);
		}
		DryRunWorld world = new DryRunWorld(session.schema, s);
		for (String f : failures) {
			String[] parts = f.split("@", 2);
			int nth;
			try {
				nth = parts.length == 2 ? Integer.parseInt(parts[1]) : 1;
			} catch (NumberFormatException e) {
				throw new ModelSession.UserError("--fail takes ACTION or ACTION@N with N a number, not '" + f + "'");
			}
			if (nth < 1) {
				throw new ModelSession.UserError("--fail: calls are counted from 1, not " + nth + " in '" + f + "'");
			}
			if (session.schema.actions().stream().noneMatch(a -> a.name().equals(parts[0]))) {
				throw new ModelSession.UserError("--fail: the application has no action '" + parts[0] + "'");
			}
			world.failOnCall(parts[0], nth);
		}
		RefArcRun run = new RefArcRunner(world, new SchemaGoalPlanner(modelPlanner(session)), world).run(instance);
		for (Status status : run.statuses()) {
			spec.commandLine().getOut().println(status);
		}
		return run.outcome() == RefArcRun.Outcome.COMPLETED ? 0 : 1;
	}

	private GoalSolver modelPlanner(ModelSession session) {
		PddlPlanner engine = PlannerOption.resolve(planner);
		return new GoalSolver(session.schema, engine, Duration.ofMillis((long) (planningTimeout * 1000)));
	}

	/** The task on a VDA 5050 robot: the Status stream is printed as it happens (actions take real time). */
	private int runOnRobot(ModelSession session, State situation, ModelTask instance) {
		if (!failures.isEmpty()) {
			throw new ModelSession.UserError("--fail injects failures into the dry run; it cannot be combined with --robots");
		}
		if (!robots.startsWith("vda5050:")) {
			throw new ModelSession.UserError("--robots takes vda5050:ssl://HOST:PORT (or vda5050:tcp://HOST:PORT), not '" + robots + "'");
		}
		PrintWriter out = spec.commandLine().getOut();
		credentials.apply();
		MqttCredentialsOption.warnIfPlain("run", robots.substring("vda5050:".length()), spec.commandLine().getErr());
		GoalSolver modelPlanner = modelPlanner(session);
		try (MasterControl master = MasterControl.connect(robots.substring("vda5050:".length()), VdaTimeouts.defaults(),
				line -> spec.commandLine().getErr().println(line))) {
			RemoteAgv agv = master.agv(serial);
			if (!agv.awaitOnline()) {
				throw new ModelSession.UserError("no VDA 5050 robot '" + serial + "' online on " + master.broker() + " within "
						+ (int) VdaTimeouts.defaults().onlineSeconds() + " s (start one: ./triad robot --serial " + serial + " --broker "
						+ master.broker() + ")");
			}
			ModelAgvActors actors = new ModelAgvActors(session.schema, situation, agv);
			RefArcRun run = new RefArcRunner(actors, new SchemaGoalPlanner(modelPlanner), actors).run(instance, out::println);
			return run.outcome() == RefArcRun.Outcome.COMPLETED ? 0 : 1;
		} catch (BrokerUnreachableException | IllegalArgumentException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
	}
}
