package org.triad.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.generator.arc.ArcJavaGeneratorMain;

/**
 * refarc/build.gradle.kts generates RefArc's Java by running {@link ArcJavaGeneratorMain} on
 * src/main/arc; the Maven build runs xtext-maven-plugin with ArcJavaGeneratorSetup. Both must write
 * the same files (this Gradle cannot run Kotlin build scripts, so the program is run as the script runs it).
 */
class RefArcGradleGenerationTest {
	private static final Path REFARC = Path.of("..").toAbsolutePath().normalize().resolve("refarc");

	@TempDir
	Path tmp;

	@Test
	void theGradleBuildsGeneratorGeneratesWhatRefArcsMavenBuildGenerates() throws Exception {
		Path maven = REFARC.resolve("target/generated-sources/arc");
		assertTrue(Files.isDirectory(maven), "the Maven build of refarc runs before this module in the reactor and leaves " + maven);
		Path gradle = tmp.resolve("generated/sources/arc");

		// the arguments of refarc/build.gradle.kts's generateArchitecture, whose working directory is refarc/
		int status = ArcJavaGeneratorMain.run(new String[] { REFARC.resolve("src/main/arc").toString(), gradle.toString() }, System.out,
				System.err);
		assertEquals(0, status);

		Map<String, String> expected = GenerateModelsTest.sources(maven);
		assertEquals(expected.keySet(), GenerateModelsTest.sources(gradle).keySet());
		assertEquals(expected, GenerateModelsTest.sources(gradle));
		assertTrue(expected.containsKey("org/triad/refarc/ControllerTOP.java") && expected.containsKey("org/triad/refarc/RefArc.java"),
				expected.keySet().toString());
	}
}
