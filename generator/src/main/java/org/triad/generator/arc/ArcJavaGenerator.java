package org.triad.generator.arc;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.triad.dsl.triad.ClassDiagram;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.resource.Resource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.arc.ArcModel;

/**
 * Generates Java from every .arc model below a folder outside an Xtext builder (tests, tools).
 * Maven builds use {@code xtext-maven-plugin} with {@link ArcJavaGeneratorSetup} instead.
 */
public final class ArcJavaGenerator {
	private ArcJavaGenerator() {
	}

	/**
	 * Generates the components of the models below {@code models} into {@code output} (emptied first, so
	 * removed models leave no stale classes); models below {@code libraries} are only linked against.
	 * Model errors fail with {@code path:line:col: error CODE: message}.
	 */
	public static List<Path> generate(Path models, Path output, HandwrittenCode handwritten, List<Path> libraries) {
		LoadedApplication app = ApplicationAssembler.load(models, libraries);
		String errors = app.diagnostics().stream().filter(d -> d.severity() == ModelDiagnostic.Severity.ERROR)
				.map(d -> d.format(app.root())).collect(Collectors.joining("\n"));
		if (!errors.isEmpty()) {
			throw new IllegalStateException("the .arc models have errors:\n" + errors);
		}
		ArcNames names = new ArcNames();
		List<ClassDiagram> diagrams = new ArrayList<>();
		for (Resource r : app.resourceSet().getResources()) {
			for (EObject root : r.getContents()) {
				if (root instanceof ClassDiagram cd) {
					diagrams.add(cd);
				}
			}
		}
		names.useDataTypes(DataTypes.of(diagrams));
		ArcGenerator generator = new ArcGenerator(names, handwritten);
		List<Path> written = new ArrayList<>();
		try {
			deleteRecursively(output);
			for (Map.Entry<String, String> file : names.dataTypes().files().entrySet()) {
				Path target = output.resolve(file.getKey());
				Files.createDirectories(target.getParent());
				Files.writeString(target, file.getValue());
				written.add(target);
			}
			for (Resource r : app.resourceSet().getResources()) {
				boolean own = r.getURI().isFile() && Path.of(r.getURI().toFileString()).startsWith(app.root());
				if (own && !r.getContents().isEmpty() && r.getContents().get(0) instanceof ArcModel m && m.getComponent() != null) {
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
