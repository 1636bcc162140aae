package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad solve DOMAIN PROBLEM [-o PLAN]}: a planner on its own, Triad's engine by default. */
@Command(name = "solve", mixinStandardHelpOptions = true,
		description = { "Solve a PDDL problem and print the plan as VAL reads it.",
				"Exit code: 0 solved, 1 no plan (unsolvable or out of time), 2 bad input or planner error." })
public final class SolveCommand implements Callable<Integer> {
	@Parameters(index = "0", paramLabel = "DOMAIN", description = "the PDDL domain file")
	private Path domainFile;

	@Parameters(index = "1", paramLabel = "PROBLEM", description = "the PDDL problem file")
	private Path problemFile;

	@Option(names = { "-o", "--plan" }, paramLabel = "PLAN", description = "also write the plan to this file")
	private Path planFile;

	@Option(names = "--planner", paramLabel = "PLANNER",
			description = "triad (default), pddl4j, or an external planner's command line with {domain}, {problem} and optionally {plan}")
	private String planner = "triad";

	@Option(names = "--timeout", paramLabel = "SECONDS", description = "time limit in seconds (default: ${DEFAULT-VALUE})")
	private double timeoutSeconds = 60;

	@Option(names = "--seed", paramLabel = "N",
			description = "accepted, and changes nothing: no part of planning is randomized (ties are broken by ids, budgets count work),"
					+ " so every run gives the same plan; a note beside the plan says so")
	private Long seed;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter out = spec.commandLine().getOut();
		PrintWriter err = spec.commandLine().getErr();
		if (!SolveRun.validTimeout(timeoutSeconds)) {
			throw new CommandLine.ParameterException(spec.commandLine(), "--timeout must be a positive number of seconds, not " + timeoutSeconds);
		}
		PddlPlanner engine;
		try {
			engine = PddlPlanners.byName(planner);
		} catch (IllegalArgumentException e) {
			throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
		}
		return new SolveRun(domainFile, problemFile, planFile, engine, timeoutSeconds, seed).run(out, err);
	}
}
