package org.triad.generator.arc;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@link ArcJavaGenerator} as a program, for builds that run the architecture generator as a process
 * (refarc/build.gradle.kts; Maven runs it through {@code xtext-maven-plugin} and {@link ArcJavaGeneratorSetup}):
 *
 * <pre>java org.triad.generator.arc.ArcJavaGeneratorMain MODELS OUTPUT [--library PATH]...</pre>
 *
 * As in the Maven build, a component gets a TOP class when its hand-written class is in the
 * {@code java} folder beside {@code MODELS} ({@code src/main/java} for {@code src/main/arc}).
 * Exit status: 0 generated, 1 the models have errors (their located lines on stderr), 2 bad arguments.
 */
public final class ArcJavaGeneratorMain {
	static final String USAGE = "usage: ArcJavaGeneratorMain MODELS OUTPUT [--library PATH]...";

	private ArcJavaGeneratorMain() {
	}

	public static void main(String[] args) {
		System.exit(run(args, System.out, System.err));
	}

	/** What {@link #main} does, without exiting: the exit status. */
	public static int run(String[] args, PrintStream out, PrintStream err) {
		List<String> positional = new ArrayList<>();
		List<Path> libraries = new ArrayList<>();
		for (int i = 0; i < args.length; i++) {
			if (args[i].equals("--library")) {
				if (i + 1 == args.length) {
					err.println("--library needs a folder or jar of .arc models\n" + USAGE);
					return 2;
				}
				libraries.add(Path.of(args[++i]));
			} else if (args[i].startsWith("--")) {
				err.println("unknown option " + args[i] + "\n" + USAGE);
				return 2;
			} else {
				positional.add(args[i]);
			}
		}
		if (positional.size() != 2) {
			err.println(USAGE);
			return 2;
		}
		Path models = Path.of(positional.get(0)).toAbsolutePath().normalize();
		Path output = Path.of(positional.get(1)).toAbsolutePath().normalize();
		if (!Files.isDirectory(models)) {
			err.println("the .arc models folder " + models + " does not exist");
			return 2;
		}
		for (Path library : libraries) {
			if (!Files.exists(library)) {
				err.println("the .arc model library " + library.toAbsolutePath().normalize() + " does not exist");
				return 2;
			}
		}
		List<Path> generated;
		try {
			generated = ArcJavaGenerator.generate(models, output, HandwrittenCode.in(models.resolveSibling("java")), libraries);
		} catch (IllegalStateException e) {
			// the generator's message is the whole report: one path:line:col line per error
			err.println(e.getMessage().replace("the .arc models have errors", "the .arc models in " + models + " have errors"));
			return 1;
		}
		out.println("generated " + generated.size() + " Java files from the .arc models in " + models + " into " + output);
		return 0;
	}
}
