package org.triad.cli;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

import org.triad.planner.PddlPlanner;
import org.triad.planner.PddlPlanners;

/**
 * The {@code --planner} option, checked at start-up: an unknown name, or an external planner's
 * command whose program does not exist or cannot be run, is a usage error, not four failed plannings.
 */
final class PlannerOption {
	private PlannerOption() {
	}

	static PddlPlanner resolve(String spec) {
		PddlPlanner planner;
		try {
			planner = PddlPlanners.byName(spec);
		} catch (IllegalArgumentException e) {
			throw new ModelSession.UserError("--planner: " + e.getMessage());
		}
		if (spec != null && spec.contains("{domain}")) {
			String program = spec.trim().split("\\s+", 2)[0];
			if (!runnable(program)) {
				throw new ModelSession.UserError("--planner: cannot run '" + program + "': "
						+ (program.contains("/") || program.contains(File.separator) ? "no such executable file" : "not found on PATH"));
			}
		}
		return planner;
	}

	private static boolean runnable(String program) {
		try {
			if (program.contains("/") || program.contains(File.separator)) {
				Path p = Path.of(program);
				return Files.isRegularFile(p) && Files.isExecutable(p);
			}
			String path = System.getenv("PATH");
			if (path == null) {
				return false;
			}
			for (String dir : path.split(File.pathSeparator)) {
				Path p = Path.of(dir.isEmpty() ? "." : dir, program);
				if (Files.isRegularFile(p) && Files.isExecutable(p)) {
					return true;
				}
			}
			return false;
		} catch (InvalidPathException e) {
			return false;
		}
	}
}
