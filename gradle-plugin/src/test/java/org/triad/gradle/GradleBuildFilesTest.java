package org.triad.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * The Gradle build mirrors the Maven reactor: the Kotlin build files are not run here (README, "Gradle"),
 * so this keeps them from drifting where drift is mechanical to see: every module of pom.xml has a
 * build.gradle.kts that a settings file includes, and a module's Triad dependencies are the same in
 * both builds.
 */
class GradleBuildFilesTest {
	private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
	private static final Pattern MODULE = Pattern.compile("<module>([^<]+)</module>");
	private static final Pattern ARTIFACT_ID = Pattern.compile("<artifactId>([^<]+)</artifactId>");
	private static final Pattern DEPENDENCY = Pattern.compile("<dependency>(.*?)</dependency>", Pattern.DOTALL);
	private static final Pattern TRIAD_DEPENDENCY = Pattern.compile("<groupId>org\\.triad</groupId>\\s*<artifactId>(triad-[^<]+)</artifactId>");
	private static final Pattern GRADLE_COORDINATES = Pattern.compile("\"org\\.triad:(triad-[\\w-]+):");
	private static final Pattern GRADLE_PROJECT = Pattern.compile("project\\(\":([\\w:-]+)\"\\)");
	/** Maven dependencies the Gradle build leaves out on purpose, by module folder, and why. */
	private static final Map<String, Set<String>> LEFT_OUT = Map.of(
			// the tests that compare with the Maven build's output of the hospital are excluded from the Gradle build
			"gradle-plugin", Set.of("triad-models-hospital"));

	@Test
	void everyMavenModuleHasAGradleBuildFileThatASettingsFileIncludes() throws IOException {
		String rootSettings = Files.readString(ROOT.resolve("settings.gradle.kts"));
		String toolchainSettings = Files.readString(ROOT.resolve("gradle-plugin/settings.gradle.kts"));
		for (String module : modules()) {
			assertTrue(Files.isRegularFile(ROOT.resolve(module).resolve("build.gradle.kts")), module + " has no build.gradle.kts");
			String gradleName = "\"" + module.replace('/', ':') + "\"";
			boolean included = module.equals("gradle-plugin") ? rootSettings.contains("includeBuild(\"gradle-plugin\")")
					: rootSettings.contains(gradleName) || toolchainSettings.contains("to \"" + module + "\"");
			assertTrue(included, module + " is included by neither settings.gradle.kts nor gradle-plugin/settings.gradle.kts");
		}
	}

	@Test
	void everyModuleHasTheSameTriadDependenciesInBothBuilds() throws IOException {
		Map<String, String> artifactOfFolder = new TreeMap<>();
		for (String module : modules()) {
			artifactOfFolder.put(module, artifactId(Files.readString(ROOT.resolve(module).resolve("pom.xml"))));
		}
		Map<String, Set<String>> maven = new TreeMap<>();
		Map<String, Set<String>> gradle = new TreeMap<>();
		for (String module : modules()) {
			String pom = Files.readString(ROOT.resolve(module).resolve("pom.xml"));
			// dependencies of the project, not of its build's plugins (which Gradle builds name in their own configurations)
			Set<String> mavenDependencies = triadDependencies(pom.replaceAll("(?s)<build>.*</build>", ""));
			mavenDependencies.removeAll(LEFT_OUT.getOrDefault(module, Set.of()));
			maven.put(module, mavenDependencies);

			String kts = Files.readString(ROOT.resolve(module).resolve("build.gradle.kts")).replaceAll("(?m)//.*$", "");
			Set<String> gradleDependencies = new TreeSet<>(matches(GRADLE_COORDINATES, kts));
			for (String project : matches(GRADLE_PROJECT, kts)) {
				// the toolchain build names its projects by artifactId, the root build by folder
				gradleDependencies.add(project.startsWith("triad-") ? project : artifactOfFolder.get(project.replace(':', '/')));
			}
			// a Gradle configuration that runs a Maven plugin's dependency (refarc's architecture generator) is allowed
			gradleDependencies.removeAll(difference(triadDependencies(pom), mavenDependencies));
			gradle.put(module, gradleDependencies);
		}
		assertEquals(maven, gradle);
	}

	private static List<String> modules() throws IOException {
		List<String> modules = matches(MODULE, Files.readString(ROOT.resolve("pom.xml")));
		assertTrue(modules.contains("refarc") && modules.contains("models/hospital"), modules.toString());
		return modules;
	}

	private static String artifactId(String pom) {
		// the module's own artifactId comes first once the parent's is gone
		List<String> ids = matches(ARTIFACT_ID, pom.replaceAll("(?s)<parent>.*?</parent>", ""));
		return ids.get(0);
	}

	private static Set<String> triadDependencies(String pom) {
		Set<String> result = new TreeSet<>();
		for (String dependency : matches(DEPENDENCY, pom)) {
			result.addAll(matches(TRIAD_DEPENDENCY, dependency));
		}
		return result;
	}

	private static Set<String> difference(Set<String> a, Set<String> b) {
		Set<String> d = new TreeSet<>(a);
		d.removeAll(b);
		return d;
	}

	private static List<String> matches(Pattern pattern, String text) {
		List<String> found = new java.util.ArrayList<>();
		Matcher m = pattern.matcher(text);
		while (m.find()) {
			found.add(m.group(1).trim());
		}
		return found;
	}
}
