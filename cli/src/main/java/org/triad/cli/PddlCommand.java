package org.triad.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.triad.runtime.app.State;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.PddlTranslator;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code triad pddl DIR --state S.state --goal "IsAt(ward3)" -o OUT}: the planning task a goal gives, for any planner. */
@Command(name = "pddl", mixinStandardHelpOptions = true,
		description = { "Write the PDDL domain and problem that planning a goal from a situation gives (OUT/domain.pddl, OUT/problem.pddl),",
				"exactly as the Planner component translates them at runtime; hand them to any PDDL planner." })
public final class PddlCommand implements Callable<Integer> {
	@CommandLine.Mixin
	private SituationOptions app;

	@Option(names = "--goal", required = true, paramLabel = "GOAL(args)", description = "the goal, e.g. \"IsAt(ward3)\"")
	private String goal;

	@Option(names = { "-o", "--output" }, required = true, paramLabel = "OUT", description = "folder to write domain.pddl and problem.pddl to")
	private Path out;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() throws Exception {
		OutputFolder.check(out, "-o");
		SituationOptions.Opened opened = app.open();
		ModelSession session = opened.session();
		State s = opened.state();
		ModelSession.Call call = ModelSession.parseCall(goal, s);
		ModelGoal g = new ModelGoal(session.schema, call.name(), call.args());
		PddlTranslator.Task task = new PddlTranslator(session.schema).translate(s, g.schema(), g.binding());
		Files.createDirectories(out);
		Files.writeString(out.resolve("domain.pddl"), task.domainText());
		Files.writeString(out.resolve("problem.pddl"), task.problemText());
		spec.commandLine().getOut().println("wrote " + out.resolve("domain.pddl") + " and " + out.resolve("problem.pddl"));
		return 0;
	}
}
