package org.triad.dsl.arc.generator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.resource.Resource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.arc.ArcModel;

/**
 * Generates Java from every .arc model below a folder, for builds ({@code exec-maven-plugin}).
 * Arguments: model folder, output folder (emptied first, so removed models leave no stale
 * classes), optional base Java package. Model errors fail with {@code path:line:col: error CODE: message}.
 */
public final class ArcGeneratorMain {
	private ArcGeneratorMain() {
	}

	public static void main(String[] args) {
		if (args.length < 2) {
			throw new IllegalArgumentException("usage: ArcGeneratorMain MODEL_DIR OUTPUT_DIR [BASE_PACKAGE [LIBRARY_MODEL_DIR...]]");
		}
		List<Path> libraries = new ArrayList<>();
		for (int i = 3; i < args.length; i++) {
			libraries.add(Path.of(args[i]));
		}
		List<Path> written = generate(Path.of(args[0]), Path.of(args[1]), args.length >= 3 ? args[2] : "", libraries);
		System.out.println("generated " + written.size() + " Java files from .arc models into " + args[1]);
	}

	public static List<Path> generate(Path models, Path output, String basePackage) {
		return generate(models, output, basePackage, List.of());
	}

	/** Generates the components of the models below {@code models}; those below {@code libraries} are only linked against. */
	public static List<Path> generate(Path models, Path output, String basePackage, List<Path> libraries) {
		LoadedApplication app = ApplicationAssembler.load(models, libraries);
		java.util.Set<Resource> own = new java.util.HashSet<>();
		for (Resource r : app.resourceSet().getResources()) {
			if (r.getURI().isFile() && Path.of(r.getURI().toFileString()).startsWith(app.root())) {
				own.add(r);
			}
		}
		String errors = app.diagnostics().stream().filter(d -> d.severity() == ModelDiagnostic.Severity.ERROR)
				.map(d -> d.format(app.root())).collect(Collectors.joining("\n"));
		if (!errors.isEmpty()) {
			throw new IllegalStateException("the .arc models have errors:\n" + errors);
		}
		ArcGenerator generator = new ArcGenerator(new ArcNames(basePackage));
		List<Path> written = new ArrayList<>();
		try {
			deleteRecursively(output);
			for (Resource r : own) {
				if (!r.getContents().isEmpty() && r.getContents().get(0) instanceof ArcModel m && m.getComponent() != null) {
					for (Map.Entry<String, String> file : generator.files(m.getComponent()).entrySet()) {
						Path target = output.resolve(file.getKey());
						Files.createDirectories(target.getParent());
						Files.writeString(target, file.getValue());
						written.add(target);
					}
				}
			}
		} catch (IOException e) {
			throw new UncheckedIOException("cannot write generated Java below " + output + ": " + e.getMessage(), e);
		}
		return written;
	}

	private static void deleteRecursively(Path dir) throws IOException {
		if (!Files.exists(dir)) {
			return;
		}
		try (Stream<Path> walk = Files.walk(dir)) {
			for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
				Files.delete(p);
			}
		}
	}
}
