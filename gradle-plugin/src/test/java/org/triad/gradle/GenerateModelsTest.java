package org.triad.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.gradle.api.GradleException;
import org.gradle.api.InvalidUserDataException;
import org.gradle.api.Project;
import org.gradle.api.provider.Property;
import org.gradle.api.Task;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.plugins.JavaPluginExtension;
import org.gradle.testfixtures.ProjectBuilder;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;

/**
 * The plugin in a real Gradle project model (Gradle 8.10's {@link ProjectBuilder}), its task action
 * run on copies of the example applications.
 */
class GenerateModelsTest {
	private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
	static final String ARCHITECTURE_PACKAGE_REMOVED = "triad.architecturePackage is no longer supported: the package of an .arc model is the"
			+ " Java package of its component (e.g. 'package org.triad.examples.hospital;' at the top of the .arc file); remove the setting";

	@TempDir
	Path tmp;

	@Test
	void theTaskFeedsTheMainSourceSetAndCompileJavaRunsItFirst() throws IOException {
		Project project = modelsProject("hospital", "models/hospital");
		GenerateModels task = generateModels(project);

		assertTrue(project.getPlugins().hasPlugin(JavaPlugin.class));
		assertEquals("build", task.getGroup());
		assertEquals(project.file("src/main/models"), task.getModels().get().getAsFile());
		assertEquals(project.file("src/main/arc"), task.getArchitecture().get().getAsFile());
		File output = project.getLayout().getBuildDirectory().dir("generated/sources/triad").get().getAsFile();
		assertEquals(output, task.getOutputDirectory().get().getAsFile());
		assertTrue(project.getExtensions().getByType(JavaPluginExtension.class).getSourceSets().getByName("main").getJava()
				.getSrcDirs().contains(output));
		Task compileJava = project.getTasks().getByName("compileJava");
		assertTrue(compileJava.getTaskDependencies().getDependencies(compileJava).contains(task),
				"compileJava depends on " + compileJava.getTaskDependencies().getDependencies(compileJava));
	}

	@Test
	void theModelFoldersAndSettingsAreTheInputsAndTheGeneratedFolderTheOutput() throws IOException {
		Project project = modelsProject("hospital", "models/hospital");
		TriadModelsExtension triad = project.getExtensions().getByType(TriadModelsExtension.class);
		File refarc = ROOT.resolve("refarc/src/main/arc").toFile();
		triad.getArchitectureLibraries().from(refarc);
		triad.getBasePackage().set("com.example.ward");
		GenerateModels task = generateModels(project);

		// what Gradle fingerprints for its up-to-date check (HospitalGradleBuildIT sees it work in a real build)
		Set<File> inputs = task.getInputs().getFiles().getFiles();
		assertTrue(inputs.containsAll(Set.of(project.file("src/main/models"), project.file("src/main/arc"), refarc)), inputs.toString());
		assertEquals(Set.of(task.getOutputDirectory().get().getAsFile()), task.getOutputs().getFiles().getFiles());
		Map<String, Object> properties = task.getInputs().getProperties();
		assertEquals(Map.of("basePackage", "com.example.ward"), properties);
	}

	/** What the plugin checks once the build script ran (ProjectBuilder cannot evaluate a project here; HospitalGradleBuildIT's Gradle does). */
	@Test
	void settingTheRemovedArchitecturePackageFailsWithWhatToDoInstead() throws IOException {
		Project project = modelsProject("hospital", "models/hospital");
		TriadModelsExtension triad = project.getExtensions().getByType(TriadModelsExtension.class);
		TriadModelsPlugin.rejectRemovedSettings(triad); // not set: nothing to reject

		@SuppressWarnings("deprecation")
		Property<String> architecturePackage = triad.getArchitecturePackage();
		architecturePackage.set("org.triad");
		InvalidUserDataException e = assertThrows(InvalidUserDataException.class, () -> TriadModelsPlugin.rejectRemovedSettings(triad));
		assertEquals(ARCHITECTURE_PACKAGE_REMOVED, e.getMessage());
		assertFalse(generateModels(project).getInputs().getProperties().containsKey("architecturePackage"));
	}

	@Test
	void theHospitalGeneratesExactlyWhatItsMavenBuildGenerates() throws IOException {
		Path maven = ROOT.resolve("models/hospital/target/generated-sources");
		assertTrue(Files.isDirectory(maven.resolve("triad")) && Files.isDirectory(maven.resolve("arc")),
				"the Maven build of models/hospital runs before this module in the reactor and leaves " + maven);
		Project project = modelsProject("hospital", "models/hospital");
		TriadModelsExtension triad = project.getExtensions().getByType(TriadModelsExtension.class);
		// models/hospital/pom.xml links against RefArc's models in refarc's jar, models/hospital/build.gradle.kts against its sources
		triad.getArchitectureLibraries().from(ROOT.resolve("refarc/src/main/arc").toFile());
		GenerateModels task = generateModels(project);
		task.generate();

		Map<String, String> expected = sources(maven.resolve("triad"));
		expected.putAll(sources(maven.resolve("arc")));
		Map<String, String> generated = sources(task.getOutputDirectory().get().getAsFile().toPath());
		assertEquals(expected.keySet(), generated.keySet());
		assertEquals(expected, generated);
		assertTrue(generated.containsKey("generated/hospital/IRobot.java"));
		assertTrue(generated.containsKey("org/triad/examples/hospital/VerifiedHospital.java"), generated.keySet().toString());
	}

	@Test
	void modelErrorsFailTheTaskWithTheLinesOfTriadCheckAndNoStackTrace() throws IOException {
		Project project = modelsProject("logistics", "models/logistics");
		Files.writeString(project.file("src/main/models/Broken.goal").toPath(),
				"domain LogisticsDomain;\n\ngoal Broken(Ward w) {\n  LogisticsRobot.loc() == w\n}\n");
		GenerateModels task = generateModels(project);

		GradleException e = assertThrows(GradleException.class, task::generate);
		Path models = project.file("src/main/models").toPath();
		LoadedApplication checked = ApplicationAssembler.load(models); // what ./triad check prints for the folder
		String lines = checked.diagnostics().stream().map(d -> d.format(checked.root())).collect(Collectors.joining("\n"));
		assertEquals("the models in " + models + " have errors:\n" + lines, e.getMessage());
		assertTrue(lines.startsWith("Broken.goal:3:13: error link.unknown-type: "), lines);
		assertNull(e.getCause());
		assertFalse(Files.exists(task.getOutputDirectory().get().getAsFile().toPath().resolve("generated")));
	}

	@Test
	void aMissingModelsFolderIsNamed() throws IOException {
		Path dir = Files.createDirectories(tmp.resolve("empty"));
		Project project = ProjectBuilder.builder().withProjectDir(dir.toFile()).withName("empty").build();
		project.getPluginManager().apply("org.triad.models");

		GradleException e = assertThrows(GradleException.class, generateModels(project)::generate);
		assertEquals("the models folder " + dir.resolve("src/main/models") + " does not exist: put the application's .cd, .actor,"
				+ " .goal, .task and .state files there, or point triad.models to the folder that has them", e.getMessage());
		assertNull(e.getCause());
	}

	@Test
	void aRemovedModelLeavesNoStaleClassAndThePackageIsConfigurable() throws IOException {
		Project project = modelsProject("logistics", "models/logistics");
		project.getExtensions().getByType(TriadModelsExtension.class).getBasePackage().set("com.example.rooms");
		GenerateModels task = generateModels(project);
		Path out = task.getOutputDirectory().get().getAsFile().toPath();
		task.generate();
		assertTrue(Files.exists(out.resolve("com/example/rooms/goals/IsAt.java")), sources(out).keySet().toString());

		Files.writeString(project.file("src/main/models/GoTo.task").toPath(), "domain LogisticsDomain;\n");
		task.generate();
		assertTrue(Files.exists(out.resolve("com/example/rooms/goals/IsAt.java")));
		assertFalse(sources(out).keySet().stream().anyMatch(f -> f.contains("GoTo")), sources(out).keySet().toString());
	}

	/** A Gradle project {@code name} with a copy of an example's models, the plugin applied. */
	private Project modelsProject(String name, String example) throws IOException {
		Path dir = tmp.resolve(name);
		for (String folder : new String[] { "src/main/models", "src/main/arc" }) {
			Path from = ROOT.resolve(example).resolve(folder);
			if (Files.isDirectory(from)) {
				copyTree(from, dir.resolve(folder));
			}
		}
		Project project = ProjectBuilder.builder().withProjectDir(dir.toFile()).withName(name).build();
		project.getPluginManager().apply("org.triad.models");
		return project;
	}

	private static GenerateModels generateModels(Project project) {
		return (GenerateModels) project.getTasks().getByName(TriadModelsPlugin.TASK_NAME);
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

	/** Every .java file below a source root: path relative to it, with '/' separators, and content. */
	static Map<String, String> sources(Path root) throws IOException {
		Map<String, String> files = new TreeMap<>();
		if (!Files.isDirectory(root)) {
			return files;
		}
		try (Stream<Path> walk = Files.walk(root)) {
			for (Path p : walk.filter(f -> f.toString().endsWith(".java")).toList()) {
				files.put(root.relativize(p).toString().replace(File.separatorChar, '/'), Files.readString(p));
			}
		}
		return files;
	}
}
