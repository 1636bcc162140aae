package org.triad.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarFile;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Real Gradle 8.10, assembled from Maven Central artifacts (target/gradle-8.10, see
 * src/gradle-dist/AssembleGradle.java), builds a copy of the hospital models project with the
 * org.triad.models plugin: {@code gradle generateModels build} generates exactly what the Maven build
 * generates, compiles the robotics expert's code and tests against it and runs the simulation's tests
 * with JUnit 5 in Gradle's test task (the VDA 5050 tests, which start a Mosquitto broker, are left to
 * the Maven build); a second {@code generateModels} is UP-TO-DATE (two Gradle runs: each costs a JVM
 * start and Gradle's configuration; GenerateModelsTest checks what the task declares as inputs).
 */
class HospitalGradleBuildIT {
	private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
	/** The hospital's tests that need no MQTT broker: the simulated robot and the floor plan. */
	private static final List<String> SIMULATION_TESTS = List.of("org.triad.examples.hospital.SimulatedCourierTest",
			"org.triad.examples.hospital.HospitalFloorTest");
	/** Shared by the tests' builds: Gradle instruments a build script's class path (the Triad libraries) once per user home. */
	private static final Path USER_HOME = Path.of("target/gradle-user-home").toAbsolutePath();
	private static final Path GRADLE = Path.of(System.getProperty("gradle.home", "target/gradle-8.10")).resolve("bin/gradle");

	@Test
	void gradleBuildsTheHospitalWithTheSameGeneratedSourcesAsMaven() throws Exception {
		assertTrue(Files.isExecutable(GRADLE), "the pre-integration-test phase assembles " + GRADLE);
		Path work = Path.of("target/gradle-it").toAbsolutePath();
		deleteTree(work);
		Path project = work.resolve("hospital");
		copyTree(ROOT.resolve("models/hospital/src"), project.resolve("src"));
		copyTree(Path.of("src/test/gradle/hospital"), project);
		Files.writeString(project.resolve("gradle.properties"), "triadClasspath=" + triadClasspath() + "\n"
				+ "refarcModels=" + ROOT.resolve("refarc/src/main/arc") + "\n", StandardCharsets.UTF_8);

		Run build = gradle(work, project, "generateModels", "build", "test", "--tests", SIMULATION_TESTS.get(0), "--tests",
				SIMULATION_TESTS.get(1));
		assertEquals(0, build.exit(), build.output());
		assertTrue(build.output().contains("BUILD SUCCESSFUL"), build.output());
		assertTrue(build.output().contains("> Task :generateModels\n"), build.output());

		Path maven = ROOT.resolve("models/hospital/target/generated-sources");
		Map<String, String> expected = GenerateModelsTest.sources(maven.resolve("triad"));
		expected.putAll(GenerateModelsTest.sources(maven.resolve("arc")));
		Map<String, String> generated = GenerateModelsTest.sources(project.resolve("build/generated/sources/triad"));
		assertFalse(expected.isEmpty(), "the Maven build of models/hospital ran before this module");
		assertEquals(expected.keySet(), generated.keySet());
		assertEquals(expected, generated);

		try (JarFile jar = new JarFile(project.resolve("build/libs/hospital.jar").toFile())) {
			assertTrue(jar.getEntry("generated/hospital/IRobot.class") != null);
			assertTrue(jar.getEntry("org/triad/examples/hospital/VerifiedHospital.class") != null);
			assertTrue(jar.getEntry("org/triad/examples/hospital/SimulatedCourier.class") != null);
		}
		assertTrue(Files.isRegularFile(project.resolve("build/classes/java/test/org/triad/examples/hospital/vda5050/VdaRobotTest.class")));
		for (String testClass : SIMULATION_TESTS) {
			Path source = project.resolve("src/test/java/" + testClass.replace('.', '/') + ".java");
			Path report = project.resolve("build/test-results/test/TEST-" + testClass + ".xml");
			assertTrue(Files.isRegularFile(report), "Gradle's test task ran " + testClass + " and reported it in " + report);
			String xml = Files.readString(report);
			assertEquals(testMethods(Files.readString(source)), reported(xml, "<testcase name=\"(\\w+)"), testClass);
			assertEquals(List.of("0"), reported(xml, "failures=\"(\\d+)\"").stream().toList(), xml);
			assertEquals(List.of("0"), reported(xml, "errors=\"(\\d+)\"").stream().toList(), xml);
			assertEquals(List.of("0"), reported(xml, "skipped=\"(\\d+)\"").stream().toList(), xml);
		}

		Run again = gradle(work, project, "generateModels");
		assertEquals(0, again.exit(), again.output());
		assertTrue(again.output().contains("> Task :generateModels UP-TO-DATE"), again.output());
	}

	@Test
	void aBuildThatSetsTheRemovedArchitecturePackageFailsItsConfigurationWithWhatToDo() throws Exception {
		assertTrue(Files.isExecutable(GRADLE), "the pre-integration-test phase assembles " + GRADLE);
		Path work = Path.of("target/gradle-it-legacy").toAbsolutePath();
		deleteTree(work);
		Path project = Files.createDirectories(work.resolve("legacy"));
		Files.writeString(project.resolve("settings.gradle"), "rootProject.name = 'legacy'\n");
		Files.writeString(project.resolve("build.gradle"), String.join("\n",
				"buildscript { dependencies { classpath files(triadClasspath.split(File.pathSeparator)) } }",
				"apply plugin: 'org.triad.models'",
				"triad { architecturePackage = 'org.triad' }", ""));
		Files.writeString(project.resolve("gradle.properties"), "triadClasspath=" + triadClasspath() + "\n", StandardCharsets.UTF_8);

		Run build = gradle(work, project, "generateModels");
		assertEquals(1, build.exit(), build.output());
		assertTrue(build.output().contains("* What went wrong:\nA problem occurred configuring root project 'legacy'.\n> "
				+ GenerateModelsTest.ARCHITECTURE_PACKAGE_REMOVED + "\n"), build.output());
		assertFalse(build.output().contains("\tat "), "no stack trace:\n" + build.output());
	}

	/** The names of a JUnit 5 test class's test methods. */
	private static Set<String> testMethods(String source) {
		return reported(source, "@Test\\s+(?:public\\s+)?void\\s+(\\w+)\\(");
	}

	/** Every first group of {@code regex} in {@code text}. */
	private static Set<String> reported(String text, String regex) {
		Set<String> found = new TreeSet<>();
		Matcher m = Pattern.compile(regex).matcher(text);
		while (m.find()) {
			found.add(m.group(1));
		}
		return found;
	}

	/** The Triad libraries and their dependencies: this JVM's class path without the hospital's own Maven build and this module's tests. */
	private static String triadClasspath() {
		return Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
				.filter(e -> !e.contains("triad-models-hospital") && !e.replace('\\', '/').contains("models/hospital/target"))
				.filter(e -> !e.endsWith("test-classes"))
				.collect(Collectors.joining(File.pathSeparator));
	}

	record Run(int exit, String output) {
	}

	private static Run gradle(Path work, Path project, String... tasks) throws IOException, InterruptedException {
		List<String> command = new ArrayList<>(List.of(GRADLE.toString(), "--offline", "--no-daemon", "--console=plain",
				"-g", USER_HOME.toString(), "-p", project.toString()));
		command.addAll(List.of(tasks));
		Path log = work.resolve("gradle-" + tasks.length + "-" + tasks[0] + ".log");
		Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
		if (!p.waitFor(10, TimeUnit.MINUTES)) {
			p.destroyForcibly().waitFor();
			throw new AssertionError("gradle " + String.join(" ", tasks) + " did not finish in 10 minutes; see " + log);
		}
		return new Run(p.exitValue(), Files.readString(log));
	}

	private static void copyTree(Path from, Path to) throws IOException {
		try (Stream<Path> walk = Files.walk(from)) {
			for (Path p : walk.toList()) {
				Path target = to.resolve(from.relativize(p).toString());
				if (Files.isDirectory(p)) {
					Files.createDirectories(target);
				} else {
					Files.copy(p, target);
				}
			}
		}
	}

	private static void deleteTree(Path dir) throws IOException {
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
