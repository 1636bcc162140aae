package org.triad.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/**
 * {@code triad demo}: the hospital application's own demo ({@code org.triad.examples.hospital.HospitalDemo}
 * in {@code models/hospital}), launched on that application's class path; every argument goes to it.
 */
@Command(name = "demo",
		description = { "Run the hospital demo: the evaluation's delivery task (collect gauze in storage, deliver it to ward 1),",
				"planned at runtime through RefArc and executed by a simulated robot on the hospital floor (dyn4j),",
				"printing every step with the robot's position, then writing pictures of the run (PNG, GIF, HTML).",
				"Options: [-o DIR] [--seed N] [--close-fire-door-at SECONDS] (see 'triad demo --help').",
				"Exit code: 0 when the task completed, 1 when it was aborted, 2 for bad options." })
public final class DemoCommand implements Callable<Integer> {
	/** Where the demo's application project is, relative to the Triad checkout. */
	static final String APPLICATION = "models/hospital";

	@Parameters(paramLabel = "ARGS", arity = "0..*", description = "the demo's options, passed on")
	private List<String> args = new ArrayList<>();

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		return ApplicationLauncher.bundled(APPLICATION).run("demo", args, spec.commandLine().getOut(), spec.commandLine().getErr());
	}
}
