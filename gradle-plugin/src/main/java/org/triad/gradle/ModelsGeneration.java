package org.triad.gradle;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.generator.arc.ArcJavaGenerator;
import org.triad.generator.arc.HandwrittenCode;
import org.triad.generator.java.TriadJavaGenerator;
import org.triad.generator.java.TriadNames;

/**
 * What {@code generateModels} does, free of Gradle so that it is testable on its own: checks the
 * application's models and generates their Java through the entry points the Maven build and
 * {@code ./triad generate} use ({@link TriadJavaGenerator}, {@link ArcJavaGenerator}), so the three
 * builds cannot drift apart.
 */
public final class ModelsGeneration {
	/**
	 * What to generate.
	 *
	 * @param models                the application's model folder (.cd .actor .goal .task .state); must exist
	 * @param architecture          the .arc model folder; skipped when absent or missing
	 * @param architectureLibraries .arc folders the architecture links against (e.g. RefArc's), not generated
	 * @param basePackage           base Java package of the application, or null for {@code generated.<application>}
	 * @param output                the folder to fill; emptied first, so a removed model leaves no stale class
	 */
	public record Request(Path models, Path architecture, List<Path> architectureLibraries, String basePackage, Path output) {
		public Request {
			architectureLibraries = List.copyOf(architectureLibraries);
		}
	}

	/**
	 * What was generated.
	 *
	 * @param applicationFiles  the application's Java files
	 * @param architectureFiles the architecture's Java files
	 * @param basePackage       the application's package
	 * @param warnings          the models' warnings, as {@code ./triad check} prints them
	 */
	public record Outcome(List<Path> applicationFiles, List<Path> architectureFiles, String basePackage, List<String> warnings) {
	}

	/** Bad input: a missing folder or models with errors; the message is what the user should see, in full. */
	public static final class ModelsProblem extends RuntimeException {
		private static final long serialVersionUID = 1L;

		public ModelsProblem(String message) {
			super(message);
		}
	}

	private ModelsGeneration() {
	}

	public static Outcome run(Request request) {
		Path models = request.models().toAbsolutePath().normalize();
		if (!Files.exists(models)) {
			throw new ModelsProblem("the models folder " + models + " does not exist: put the application's .cd, .actor, .goal, .task"
					+ " and .state files there, or point triad.models to the folder that has them");
		}
		if (!Files.isDirectory(models)) {
			throw new ModelsProblem("the models folder " + models + " is a file, not a folder");
		}
		LoadedApplication app = ApplicationAssembler.load(models);
		List<String> lines = app.diagnostics().stream().map(d -> d.format(app.root())).toList();
		if (app.hasErrors()) {
			throw new ModelsProblem("the models in " + models + " have errors:\n" + String.join("\n", lines));
		}
		List<String> warnings = app.diagnostics().stream().filter(d -> !d.isError()).map(d -> d.format(app.root())).toList();
		Path output = request.output().toAbsolutePath().normalize();
		emptyFolder(output);
		String pkg = request.basePackage() == null ? TriadNames.defaultBasePackage(app.application()) : request.basePackage();
		List<Path> applicationFiles;
		try {
			applicationFiles = TriadJavaGenerator.generate(app.application(), pkg, output);
		} catch (IllegalArgumentException e) {
			throw new ModelsProblem(e.getMessage());
		}
		List<Path> architectureFiles = request.architecture() != null && Files.isDirectory(request.architecture())
				? generateArchitecture(request, output)
				: List.of();
		return new Outcome(applicationFiles, architectureFiles, pkg, warnings);
	}

	/** The architecture generator empties its own output folder, so it writes to a scratch folder first. */
	private static List<Path> generateArchitecture(Request request, Path output) {
		Path scratch;
		try {
			scratch = Files.createTempDirectory("triad-arc");
		} catch (IOException e) {
			throw new UncheckedIOException("cannot create a scratch folder for the architecture's Java: " + e.getMessage(), e);
		}
		try {
			List<Path> generated;
			try {
				Path architecture = request.architecture().toAbsolutePath().normalize();
				// as in Maven: a TOP class only for a component whose hand-written class sits in src/main/java
				generated = ArcJavaGenerator.generate(architecture, scratch, HandwrittenCode.in(architecture.resolveSibling("java")),
						request.architectureLibraries());
			} catch (IllegalStateException e) {
				// the architecture generator reports model errors as one message of path:line:col lines
				throw new ModelsProblem(e.getMessage().replace("the .arc models have errors", "the .arc models in "
						+ request.architecture().toAbsolutePath().normalize() + " have errors"));
			}
			List<Path> moved = new ArrayList<>();
			for (Path file : generated) {
				Path target = output.resolve(scratch.relativize(file).toString());
				if (Files.exists(target)) {
					throw new ModelsProblem("the architecture and the application both generate " + output.relativize(target)
							+ ": rename the component or move it to another .arc package");
				}
				Files.createDirectories(target.getParent());
				Files.move(file, target);
				moved.add(target);
			}
			return moved;
		} catch (IOException e) {
			throw new UncheckedIOException("cannot write the architecture's Java below " + output + ": " + e.getMessage(), e);
		} finally {
			deleteQuietly(scratch);
		}
	}

	private static void emptyFolder(Path dir) {
		try {
			if (Files.exists(dir)) {
				try (Stream<Path> walk = Files.walk(dir)) {
					for (Path p : walk.sorted(Comparator.reverseOrder()).filter(p -> !p.equals(dir)).toList()) {
						Files.delete(p);
					}
				}
			}
			Files.createDirectories(dir);
		} catch (IOException e) {
			throw new UncheckedIOException("cannot empty " + dir + ": " + e.getMessage(), e);
		}
	}

	private static void deleteQuietly(Path dir) {
		try (Stream<Path> walk = Files.walk(dir)) {
			for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
				Files.deleteIfExists(p);
			}
		} catch (IOException e) {
			// a scratch folder under the system's temp folder: leaving it behind harms nothing
		}
	}

}
