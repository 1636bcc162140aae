package org.triad.cli;

import java.io.PrintWriter;

import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;

/**
 * The {@code ./triad} launcher's entry. A plain {@code triad solve} runs straight away, without
 * picocli, Xtext or EMF (which set up every command by reflection, and whose signed jars the JVM
 * verifies and cannot keep in a class-data archive); every other command line goes to {@link TriadCli}.
 */
public final class TriadMain {
	private TriadMain() {
	}

	public static void main(String[] args) {
		if (args.length > 0 && args[0].equals("solve")) {
			SolveArguments a = SolveArguments.parse(args);
			PddlPlanner engine = a == null ? null : planner(a.planner);
			if (engine != null) {
				PrintWriter out = new PrintWriter(System.out, true);
				PrintWriter err = new PrintWriter(System.err, true);
				int exit;
				try {
					exit = new SolveRun(a.domain, a.problem, a.plan, engine, a.timeoutSeconds).run(out, err);
				} catch (RuntimeException e) {
					// as TriadCli's execution exception handler reports it
					err.println("triad solve: " + FailureMessage.of(e));
					exit = 2;
				}
				System.exit(exit);
			}
		}
		TriadCli.main(args);
	}

	/** The planner named, or null for a name picocli's command reports as a usage error. */
	private static PddlPlanner planner(String name) {
		try {
			return PddlPlanners.byName(name);
		} catch (IllegalArgumentException e) {
			return null;
		}
	}
}
