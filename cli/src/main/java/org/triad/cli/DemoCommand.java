package org.triad.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code triad demo}: the hospital delivery, end to end through RefArc. */
@Command(name = "demo", mixinStandardHelpOptions = true,
		description = { "Run the hospital demo: the evaluation's delivery task (collect gauze in storage, deliver it to ward 1)",
				"through RefArc, planned at runtime, against the hospital's Morning situation, printing every step." })
public final class DemoCommand implements Callable<Integer> {
	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		Path home = Path.of(System.getProperty("triad.home", "."));
		Path models = home.resolve("models/hospital/src/main/models");
		if (!Files.isDirectory(models)) {
			throw new ModelSession.UserError("cannot find the hospital models at " + models + " (run ./triad from the repository)");
		}
		spec.commandLine().getOut().println("Triad demo: hospital delivery, CollectAndDeliver(gauze, storage, ward1) from situation Morning");
		return spec.commandLine().getParent().execute("run", models.toString(), "--state", "Morning.state", "--task",
				"CollectAndDeliver(gauze, storage, ward1)");
	}
}
