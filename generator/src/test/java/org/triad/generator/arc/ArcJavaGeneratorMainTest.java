package org.triad.generator.arc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.validation.ArcIssueCodes;

/** The architecture generator as the program refarc/build.gradle.kts runs. */
class ArcJavaGeneratorMainTest {
	private static final Map<String, String> MODELS = Map.of(
			"demo/Scaler.arc", """
					package demo;
					component Scaler(int factor) {
					  port in int in;
					  port out Integer out;
					}
					""",
			"demo/Doubler.arc", """
					package demo;
					component Doubler {
					  port in int in;
					  port out Integer out;
					  Scaler scaler(2);
					  in -> scaler.in;
					  scaler.out -> out;
					}
					""");

	@TempDir
	Path work;

	private final ByteArrayOutputStream out = new ByteArrayOutputStream();
	private final ByteArrayOutputStream err = new ByteArrayOutputStream();

	@Test
	void aComponentWithHandWrittenCodeBesideTheModelsGetsATopClass() throws Exception {
		Path project = work.resolve("project");
		ArcGeneratorTest.write(project.resolve("src/main/arc"), MODELS);
		ArcGeneratorTest.write(project.resolve("src/main/java"), Map.of("demo/Doubler.java", "package demo;\n"));
		Path output = work.resolve("generated");

		assertEquals(0, run(project.resolve("src/main/arc").toString(), output.toString()), err());
		assertEquals(List.of("demo/DoublerTOP.java", "demo/ScalerTOP.java"), javaFiles(output));
		assertTrue(out().contains("generated 2 Java files"), out());
	}

	@Test
	void withoutHandWrittenCodeAComposedComponentIsItsOwnClass() throws Exception {
		Path models = work.resolve("src/main/arc");
		ArcGeneratorTest.write(models, MODELS);
		Path output = work.resolve("generated");

		assertEquals(0, run(models.toString(), output.toString()), err());
		// an atomic component's behaviour is always hand-written, so it always gets a TOP class
		assertEquals(List.of("demo/Doubler.java", "demo/ScalerTOP.java"), javaFiles(output));
	}

	@Test
	void componentsOfALibraryAreLinkedButNotGenerated() throws Exception {
		Path library = work.resolve("library");
		ArcGeneratorTest.write(library, Map.of("demo/Scaler.arc", MODELS.get("demo/Scaler.arc")));
		Path models = work.resolve("models");
		ArcGeneratorTest.write(models, Map.of("demo/Doubler.arc", MODELS.get("demo/Doubler.arc")));
		Path output = work.resolve("generated");

		assertEquals(1, run(models.toString(), output.toString()), "without the library Scaler is unknown");
		assertEquals(0, run(models.toString(), output.toString(), "--library", library.toString()), err());
		assertEquals(List.of("demo/Doubler.java"), javaFiles(output));
		assertTrue(Files.readString(output.resolve("demo/Doubler.java")).contains("Scaler"));
	}

	@Test
	void modelErrorsAreTheirLocatedLinesAndNoStackTrace() throws Exception {
		Path models = work.resolve("bad");
		ArcGeneratorTest.write(models, Map.of("Broken.arc", "package demo;\ncomponent Broken {\n  Missing part;\n}\n"));

		assertEquals(1, run(models.toString(), work.resolve("generated").toString()));
		assertTrue(err().startsWith("the .arc models in " + models + " have errors:\nBroken.arc:3:3: error " + ArcIssueCodes.UNKNOWN_COMPONENT
				+ ": unknown component type 'Missing'"), err());
		assertEquals(2, err().lines().count(), err());
		assertFalse(Files.exists(work.resolve("generated")));
	}

	@Test
	void badArgumentsAreNamed() {
		Path missing = work.resolve("nowhere");
		assertEquals(2, run(missing.toString(), work.resolve("out").toString()));
		assertEquals("the .arc models folder " + missing + " does not exist\n", err());

		err.reset();
		assertEquals(2, run(work.toString()));
		assertEquals(ArcJavaGeneratorMain.USAGE + "\n", err());

		err.reset();
		assertEquals(2, run(work.toString(), work.resolve("out").toString(), "--library"));
		assertTrue(err().startsWith("--library needs a folder or jar of .arc models\n"), err());
	}

	private int run(String... args) {
		return ArcJavaGeneratorMain.run(args, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
	}

	private String out() {
		return out.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n");
	}

	private String err() {
		return err.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n");
	}

	private static List<String> javaFiles(Path root) throws Exception {
		try (Stream<Path> walk = Files.walk(root)) {
			return walk.filter(p -> p.toString().endsWith(".java")).map(p -> root.relativize(p).toString().replace(File.separatorChar, '/'))
					.sorted().toList();
		}
	}
}
