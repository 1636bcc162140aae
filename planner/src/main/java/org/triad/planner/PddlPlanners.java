package org.triad.planner;

import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;

/**
 * Chooses a planner by configuration rather than code: {@code triad} (the built-in engine, the
 * default), the name of a planner on the class path ({@code pddl4j}), or the command line of an
 * external planner with {@code {domain}}, {@code {problem}} and optionally {@code {plan}} placeholders,
 * e.g. {@code "fast-downward.py --alias lama-first --plan-file {plan} {domain} {problem}"}.
 */
public final class PddlPlanners {
	/** The environment variable that sets the planner when no option does. */
	public static final String ENV = "TRIAD_PLANNER";

	private PddlPlanners() {
	}

	public static PddlPlanner byName(String spec) {
		String s = spec == null || spec.isBlank() ? "triad" : spec.trim();
		if (s.equals("triad")) {
			return new TriadEngine();
		}
		if (s.contains("{domain}")) {
			return new ExternalPlanner("external", s);
		}
		List<String> known = new ArrayList<>(List.of("triad"));
		for (PddlPlanner p : ServiceLoader.load(PddlPlanner.class)) {
			if (p.name().equals(s)) {
				return p;
			}
			known.add(p.name());
		}
		throw new IllegalArgumentException("unknown planner '" + s + "'; available: " + String.join(", ", known)
				+ ", or an external planner's command line with {domain} and {problem}");
	}

	/** The planner the environment configures ({@value #ENV}), else the built-in engine. */
	public static PddlPlanner configured() {
		return byName(System.getenv(ENV));
	}
}
