package org.triad.dsl.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * The assembler's rules beyond the per-code rule cases (rules/app.*): the name comes from the class
 * diagram wherever the files are, every actor of an application without class diagram is told so,
 * and architectures link against libraries in jars.
 */
class ApplicationAssemblerTest {
	private static final Path HOSPITAL = Path.of("..", "models", "hospital", "src", "main", "models");

	@Test
	void theApplicationIsNamedAfterItsClassDiagramWhateverTheFolder(@TempDir Path tmp) throws IOException {
		Path elsewhere = tmp.resolve("my-checkout").resolve("src").resolve("main").resolve("models");
		copy(HOSPITAL, elsewhere);
		Path flat = tmp.resolve("whatever");
		copy(HOSPITAL, flat);
		for (Path dir : List.of(HOSPITAL, elsewhere, flat)) {
			LoadedApplication app = ApplicationAssembler.load(dir);
			assertFalse(app.hasErrors(), () -> dir + ": " + app.diagnostics());
			assertEquals("Hospital", app.application().getName(), dir.toString());
			assertEquals("Courier", app.application().getRobot().getName());
			assertEquals("Building", app.application().getWorld().getName());
		}
	}

	@Test
	void everyActorOfAnApplicationWithoutClassDiagramIsToldSo(@TempDir Path dir) throws IOException {
		copy(HOSPITAL, dir);
		Files.delete(dir.resolve("Hospital.cd"));
		LoadedApplication app = ApplicationAssembler.load(dir);
		List<String> structure = app.diagnostics().stream().filter(d -> d.code().startsWith("app."))
				.map(d -> d.file().getFileName() + " " + d.code()).toList();
		assertEquals(List.of("Building.actor " + CommonIssueCodes.CLASS_DIAGRAM_COUNT, "Courier.actor " + CommonIssueCodes.CLASS_DIAGRAM_COUNT),
				structure);
		assertEquals(dir.getFileName().toString(), app.application().getName(), "without class diagram the folder names it");
	}

	@Test
	void architecturesLinkAgainstLibraryModelsInAJar(@TempDir Path tmp) throws IOException {
		Path jar = tmp.resolve("lamps.jar");
		try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
			entry(out, "triad-models/", null);
			entry(out, "triad-models/lamps/", null);
			entry(out, "triad-models/lamps/Lamp.arc", "package lamps;\ncomponent Lamp {\n  port in Boolean on;\n}\n");
			entry(out, "org/example/Other.class", "not a model");
		}
		List<URI> listed = ModelLibraries.inJar(jar);
		assertEquals(List.of("lamps/Lamp.arc"), listed.stream().map(ModelLibraries::relativePath).toList());
		try (URLClassLoader loader = new URLClassLoader(new URL[] { jar.toUri().toURL() }, null)) {
			assertEquals(listed, ModelLibraries.onClassPath(loader), "the same files found through a class loader");
		}

		Path app = tmp.resolve("app");
		Files.createDirectories(app);
		Files.writeString(app.resolve("Room.arc"), "package room;\nimport lamps.Lamp;\ncomponent Room {\n  port in Boolean power;\n  Lamp ceiling;\n  power -> ceiling.on;\n}\n");
		LoadedApplication without = ApplicationAssembler.load(app);
		assertTrue(without.diagnostics().stream().anyMatch(d -> d.isError() && d.message().contains("Lamp")),
				() -> "without the library 'Lamp' is unknown: " + without.diagnostics());
		LoadedApplication with = ApplicationAssembler.load(app, List.of(jar));
		assertEquals(List.of(), with.diagnostics().stream().map(d -> d.format(with.root())).toList());
	}

	private static void entry(JarOutputStream out, String name, String content) throws IOException {
		out.putNextEntry(new JarEntry(name));
		if (content != null) {
			out.write(content.getBytes(StandardCharsets.UTF_8));
		}
		out.closeEntry();
	}

	private static void copy(Path from, Path to) throws IOException {
		try (Stream<Path> walk = Files.walk(from)) {
			for (Path p : walk.filter(Files::isRegularFile).toList()) {
				Path target = to.resolve(from.relativize(p).toString());
				Files.createDirectories(target.getParent());
				try (OutputStream o = Files.newOutputStream(target)) {
					Files.copy(p, o);
				}
			}
		}
	}
}
