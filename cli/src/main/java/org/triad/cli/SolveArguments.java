package org.triad.cli;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;

/**
 * The arguments of {@code triad solve} in their plain form ({@code DOMAIN PROBLEM}, {@code -o}/{@code --plan PLAN},
 * {@code --planner NAME}, {@code --timeout SECONDS}, {@code --seed N}, each value its own argument), read without picocli,
 * whose reflection over every command costs a small solve most of its start-up. Anything else (help,
 * {@code --opt=value}, {@code @file}s, {@code --}, a repeated or unknown option, a value that is not
 * valid) is left to picocli ({@link #parse} answers null), so usage errors read exactly as before.
 */
final class SolveArguments {
	Path domain;
	Path problem;
	Path plan;
	String planner = "triad";
	double timeoutSeconds = 60;
	/** {@code --seed N}, or null */
	Long seed;

	private SolveArguments() {
	}

	/** @param args the whole command line, {@code args[0]} being {@code solve}; null when picocli must read it */
	static SolveArguments parse(String[] args) {
		SolveArguments a = new SolveArguments();
		boolean planSet = false;
		boolean plannerSet = false;
		boolean timeoutSet = false;
		boolean seedSet = false;
		int positional = 0;
		try {
			for (int i = 1; i < args.length; i++) {
				String arg = args[i];
				if (!plain(arg)) {
					if (i + 1 >= args.length || !plain(args[i + 1])) {
						return null;
					}
					String value = args[++i];
					switch (arg) {
						case "-o":
						case "--plan":
							if (planSet) {
								return null;
							}
							planSet = true;
							a.plan = Path.of(value);
							break;
						case "--planner":
							if (plannerSet) {
								return null;
							}
							plannerSet = true;
							a.planner = value;
							break;
						case "--timeout":
							if (timeoutSet) {
								return null;
							}
							timeoutSet = true;
							a.timeoutSeconds = Double.parseDouble(value);
							if (!SolveRun.validTimeout(a.timeoutSeconds)) {
								return null;
							}
							break;
						case "--seed":
							if (seedSet) {
								return null;
							}
							seedSet = true;
							a.seed = Long.parseLong(value);
							break;
						default:
							return null;
					}
				} else if (positional == 0) {
					a.domain = Path.of(arg);
					positional++;
				} else if (positional == 1) {
					a.problem = Path.of(arg);
					positional++;
				} else {
					return null;
				}
			}
		} catch (NumberFormatException | InvalidPathException e) {
			return null;
		}
		return positional == 2 ? a : null;
	}

	/** An argument picocli would take as it is: no option, no {@code @file}, not empty. */
	private static boolean plain(String arg) {
		return !arg.isEmpty() && arg.charAt(0) != '-' && arg.charAt(0) != '@';
	}
}
