package org.triad.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code triad check DIR}: loads and checks every model file below DIR. */
@Command(name = "check", mixinStandardHelpOptions = true,
		description = { "Load every model file (.cd .actor .goal .task .state) below DIR, link and check them together.",
				"Prints each finding as 'path:line:col: error|warning CODE: message' (path relative to DIR).",
				"Exit code: 0 without errors, 1 with errors, 2 when DIR cannot be read." })
public final class CheckCommand implements Callable<Integer> {
	@Parameters(index = "0", paramLabel = "DIR", description = "the application's folder")
	private Path dir;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		if (!Files.isDirectory(dir)) {
			spec.commandLine().getErr().println("triad check: not a folder: " + dir);
			return 2;
		}
		LoadedApplication app = ApplicationAssembler.load(dir);
		for (ModelDiagnostic d : app.diagnostics()) {
			spec.commandLine().getOut().println(d.format(app.root()));
		}
		return app.hasErrors() ? 1 : 0;
	}
}
