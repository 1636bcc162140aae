package org.triad.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.generator.java.TriadJavaGenerator;
import org.triad.generator.java.TriadNames;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad generate DIR -o OUT}: what a models project's Maven build generates, outside Maven. */
@Command(name = "generate", mixinStandardHelpOptions = true,
		description = { "Check the models below DIR and generate the application's Java into OUT: domain classes, IRobot, IWorld,",
				"goal and task classes, the application schema, the StateProvider and ActionExecutor (as 'mvn generate-sources' does).",
				"Exit code: 0 generated, 1 model errors (printed as path:line:col: error CODE: message), 2 bad input." })
public final class GenerateCommand implements Callable<Integer> {
	@Parameters(index = "0", paramLabel = "DIR", description = "the application's model folder")
	private Path dir;

	@Option(names = { "-o", "--output" }, required = true, paramLabel = "OUT", description = "the folder to write Java sources to")
	private Path out;

	@Option(names = { "-p", "--package" }, paramLabel = "PACKAGE", description = "the base package (default: generated.<application>)")
	private String basePackage;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		if (!Files.isDirectory(dir)) {
			throw new ModelSession.UserError("not a folder: " + dir);
		}
		OutputFolder.check(out, "-o");
		LoadedApplication app = ApplicationAssembler.load(dir);
		for (ModelDiagnostic d : app.diagnostics()) {
			spec.commandLine().getOut().println(d.format(app.root()));
		}
		if (app.hasErrors()) {
			return 1;
		}
		String pkg = basePackage == null ? TriadNames.defaultBasePackage(app.application()) : basePackage;
		List<Path> written;
		try {
			written = TriadJavaGenerator.generate(app.application(), pkg, out);
		} catch (IllegalArgumentException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
		spec.commandLine().getOut().println("generated " + written.size() + " Java files of package " + pkg + " into " + out);
		return 0;
	}
}
