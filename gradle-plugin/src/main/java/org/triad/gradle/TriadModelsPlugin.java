package org.triad.gradle;

import org.gradle.api.InvalidUserDataException;
import org.gradle.api.Plugin;
import org.gradle.api.Project;
import org.gradle.api.file.ProjectLayout;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.plugins.JavaPluginExtension;
import org.gradle.api.tasks.SourceSet;
import org.gradle.api.tasks.TaskProvider;

/**
 * {@code plugins { id("org.triad.models") }}: a Java project whose {@code generateModels} task turns
 * {@code src/main/models} and {@code src/main/arc} into {@code build/generated/sources/triad}, which
 * the main source set compiles (so {@code compileJava} runs {@code generateModels} first).
 */
public class TriadModelsPlugin implements Plugin<Project> {
	public static final String TASK_NAME = "generateModels";
	public static final String EXTENSION_NAME = "triad";
	public static final String OUTPUT_PATH = "generated/sources/triad";
	static final String ARCHITECTURE_PACKAGE_REMOVED = "triad.architecturePackage is no longer supported: the package of an .arc"
			+ " model is the Java package of its component (e.g. 'package org.triad.examples.hospital;' at the top of the .arc file);"
			+ " remove the setting";

	@Override
	public void apply(Project project) {
		project.getPluginManager().apply(JavaPlugin.class);
		ProjectLayout layout = project.getLayout();
		TriadModelsExtension triad = project.getExtensions().create(EXTENSION_NAME, TriadModelsExtension.class);
		triad.getModels().convention(layout.getProjectDirectory().dir("src/main/models"));
		triad.getArchitecture().convention(layout.getProjectDirectory().dir("src/main/arc"));
		project.afterEvaluate(p -> rejectRemovedSettings(triad));

		TaskProvider<GenerateModels> generate = project.getTasks().register(TASK_NAME, GenerateModels.class, task -> {
			task.setGroup("build");
			task.setDescription("Checks the Triad models and generates their Java into build/" + OUTPUT_PATH + ".");
			task.getModels().set(triad.getModels());
			task.getArchitecture().set(triad.getArchitecture());
			task.getArchitectureLibraries().from(triad.getArchitectureLibraries());
			task.getBasePackage().set(triad.getBasePackage());
			task.getOutputDirectory().convention(layout.getBuildDirectory().dir(OUTPUT_PATH));
		});
		// a source folder given as the task's output carries the task dependency to compileJava and the IDE import
		project.getExtensions().getByType(JavaPluginExtension.class).getSourceSets().getByName(SourceSet.MAIN_SOURCE_SET_NAME)
				.getJava().srcDir(generate.flatMap(GenerateModels::getOutputDirectory));
	}

	/** Fails the configuration of a build that sets what no longer has an effect, saying what to do instead. */
	static void rejectRemovedSettings(TriadModelsExtension triad) {
		@SuppressWarnings("deprecation")
		boolean architecturePackageSet = triad.getArchitecturePackage().isPresent();
		if (architecturePackageSet) {
			throw new InvalidUserDataException(ARCHITECTURE_PACKAGE_REMOVED);
		}
	}
}
