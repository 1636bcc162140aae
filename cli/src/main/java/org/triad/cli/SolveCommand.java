package org.triad.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;

import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;
import org.triad.planner.SolveResult;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

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

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter out = spec.commandLine().getOut();
		PrintWriter err = spec.commandLine().getErr();
		if (!(timeoutSeconds > 0) || Double.isInfinite(timeoutSeconds)) {
			throw new CommandLine.ParameterException(spec.commandLine(), "--timeout must be a positive number of seconds, not " + timeoutSeconds);
		}
		PddlPlanner engine;
		try {
			engine = PddlPlanners.byName(planner);
		} catch (IllegalArgumentException e) {
			throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
		}
		Domain domain;
		Problem problem;
		try {
			domain = PddlParser.parseDomain(domainFile);
			problem = PddlParser.parseProblem(problemFile);
		} catch (PddlParseException e) {
			err.println("error: " + e.getMessage());
			return 2;
		} catch (NoSuchFileException e) {
			err.println("error: no such file: " + e.getFile());
			return 2;
		} catch (IOException e) {
			err.println("error: cannot read input: " + e.getMessage());
			return 2;
		}
		SolveResult r = engine.solve(domain, problem, Duration.ofMillis((long) (timeoutSeconds * 1000)));
		switch (r.status()) {
			case SOLVED -> {
				String text = r.plan().toPddl();
				out.print(text);
				out.flush();
				if (planFile != null) {
					try {
						Files.writeString(planFile, text);
					} catch (IOException e) {
						err.println("error: cannot write the plan file " + planFile + ": " + e);
						return 2;
					}
				}
				return 0;
			}
			case UNSOLVABLE -> {
				err.println("no plan: problem is unsolvable (" + r.message() + ")");
				return 1;
			}
			case TIMEOUT -> {
				err.println("no plan: time limit of " + timeoutSeconds + " s reached");
				return 1;
			}
			default -> {
				err.println("error: " + r.message());
				return 2;
			}
		}
	}
}
