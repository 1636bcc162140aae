package org.triad.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;

import org.triad.planner.PddlPlanner;
import org.triad.planner.SolveResult;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * One {@code triad solve} after its arguments are checked: read, plan, print, and the exit code
 * (0 solved, 1 no plan, 2 bad input or planner error). Shared by {@link SolveCommand} and the
 * launcher's picocli-free entry ({@link TriadMain}), so both answer alike; it loads the planner and
 * nothing of the command-line library.
 */
final class SolveRun {
	private final Path domainFile;
	private final Path problemFile;
	private final Path planFile;
	private final PddlPlanner engine;
	private final double timeoutSeconds;
	private final Long seed;

	/** @param planFile where to write the plan too, or null */
	SolveRun(Path domainFile, Path problemFile, Path planFile, PddlPlanner engine, double timeoutSeconds) {
		this(domainFile, problemFile, planFile, engine, timeoutSeconds, null);
	}

	/** @param seed the {@code --seed} given, or null */
	SolveRun(Path domainFile, Path problemFile, Path planFile, PddlPlanner engine, double timeoutSeconds, Long seed) {
		this.seed = seed;
		this.domainFile = domainFile;
		this.problemFile = problemFile;
		this.planFile = planFile;
		this.engine = engine;
		this.timeoutSeconds = timeoutSeconds;
	}

	/**
	 * What {@code --seed} does, in its help and beside the plan: nothing, because no planner part is
	 * randomized (a seed that changed nothing silently would let a user believe two seeds gave two
	 * samples). {@code SEED} stands for the seed given.
	 */
	static final String SEED_NOTE = "seed SEED changes nothing: the planning engine has no randomized part"
			+ " (ties are broken by ids, budgets count work), so every seed and every run gives this plan";

	/** True for the time limits {@code --timeout} accepts: positive and finite. */
	static boolean validTimeout(double seconds) {
		return seconds > 0 && !Double.isInfinite(seconds);
	}

	int run(PrintWriter out, PrintWriter err) {
		long start = System.nanoTime();
		long timeoutNanos = (long) (timeoutSeconds * 1e9);
		Domain domain;
		Problem problem;
		// the timeout holds while reading too: the files are parsed on a daemon thread that is left
		// behind if it takes longer (the process ends right after)
		java.util.concurrent.FutureTask<Object[]> parsing = new java.util.concurrent.FutureTask<>(
				() -> {
					Domain d = PddlParser.parseDomain(domainFile);
					// read against the domain: a numeric value the problem needs and can never have is a located error
					return new Object[] { d, PddlParser.parseProblem(problemFile, d) };
				});
		Thread reader = new Thread(parsing, "triad-solve-parse");
		reader.setDaemon(true);
		reader.start();
		try {
			Object[] parsed = parsing.get(timeoutNanos, java.util.concurrent.TimeUnit.NANOSECONDS);
			domain = (Domain) parsed[0];
			problem = (Problem) parsed[1];
		} catch (java.util.concurrent.TimeoutException e) {
			parsing.cancel(true);
			err.println("no plan: time limit of " + timeoutSeconds + " s reached while parsing");
			return 1;
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			err.println("error: interrupted while parsing");
			return 2;
		} catch (java.util.concurrent.ExecutionException e) {
			Throwable cause = e.getCause();
			if (cause instanceof PddlParseException) {
				err.println("error: " + cause.getMessage());
			} else if (cause instanceof NoSuchFileException n) {
				err.println("error: no such file: " + n.getFile());
			} else if (cause instanceof IOException) {
				err.println("error: cannot read input: " + cause.getMessage());
			} else if (cause instanceof OutOfMemoryError) {
				err.println("error: out of memory while parsing: the input needs more than the memory given ("
						+ (Runtime.getRuntime().maxMemory() >> 20) + " MB)");
			} else {
				err.println("error: cannot read input: " + cause);
			}
			return 2;
		}
		long left = Math.max(0, timeoutNanos - (System.nanoTime() - start));
		SolveResult r = engine.solve(domain, problem, Duration.ofNanos(left));
		switch (r.status()) {
			case SOLVED: {
				java.util.OptionalDouble metric = org.triad.planner.PlanValidator.metricValue(domain, problem, r.plan());
				String text = metric.isPresent() ? r.plan().toPddl(metric.getAsDouble()) : r.plan().toPddl();
				out.print(text);
				out.flush();
				if (seed != null) {
					// printed with the plan: a script that passes a seed learns that it decides nothing
					err.println("note: " + (engine instanceof org.triad.planner.TriadEngine ? SEED_NOTE.replace("SEED", Long.toString(seed))
							: "seed " + seed + " is not passed on to the planner named by --planner"));
				}
				if (r.isBestSoFar()) {
					// valid, but not the engine's deterministic answer: a longer --timeout gives that
					err.println("note: " + r.message() + " (a longer --timeout gives the same plan on every run)");
				}
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
			case UNSOLVABLE:
				err.println("no plan: problem is unsolvable (" + r.message() + ")");
				return 1;
			case TIMEOUT:
				err.println("no plan: time limit of " + timeoutSeconds + " s reached"
						+ (r.message().startsWith("time limit reached while") ? r.message().substring("time limit reached".length()) : ""));
				return 1;
			default:
				err.println("error: " + r.message());
				return 2;
		}
	}
}
