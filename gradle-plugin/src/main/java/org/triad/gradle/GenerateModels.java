package org.triad.gradle;

import java.io.File;
import java.util.List;

import org.gradle.api.DefaultTask;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.DirectoryProperty;
import org.gradle.api.provider.Property;
import org.gradle.api.tasks.CacheableTask;
import org.gradle.api.tasks.Input;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.Optional;
import org.gradle.api.tasks.OutputDirectory;
import org.gradle.api.tasks.PathSensitive;
import org.gradle.api.tasks.PathSensitivity;
import org.gradle.api.tasks.TaskAction;

/**
 * Checks a models project's models and generates their Java. Every model folder is an input and the
 * generated folder the output, so Gradle skips the task (UP-TO-DATE) while no model changed. The
 * folders are {@code @InputFiles} rather than {@code @InputDirectory} so that a missing models folder
 * reaches {@link ModelsGeneration}'s message instead of Gradle's generic validation error.
 */
@CacheableTask
public abstract class GenerateModels extends DefaultTask {
	@InputFiles
	@PathSensitive(PathSensitivity.RELATIVE)
	public abstract DirectoryProperty getModels();

	@InputFiles
	@Optional
	@PathSensitive(PathSensitivity.RELATIVE)
	public abstract DirectoryProperty getArchitecture();

	@InputFiles
	@PathSensitive(PathSensitivity.RELATIVE)
	public abstract ConfigurableFileCollection getArchitectureLibraries();

	@Input
	@Optional
	public abstract Property<String> getBasePackage();

	@OutputDirectory
	public abstract DirectoryProperty getOutputDirectory();

	@TaskAction
	public void generate() {
		ModelsGeneration.Outcome outcome;
		try {
			outcome = ModelsGeneration.run(new ModelsGeneration.Request(
					getModels().get().getAsFile().toPath(),
					getArchitecture().isPresent() ? getArchitecture().get().getAsFile().toPath() : null,
					getArchitectureLibraries().getFiles().stream().map(File::toPath).toList(),
					getBasePackage().getOrNull(),
					getOutputDirectory().get().getAsFile().toPath()));
		} catch (ModelsGeneration.ModelsProblem e) {
			// the message is the whole report (located diagnostics); Gradle shows it without a stack trace
			throw new GradleException(e.getMessage());
		}
		List<String> warnings = outcome.warnings();
		warnings.forEach(getLogger()::warn);
		getLogger().info("generated {} Java files of package {} and {} from .arc models into {}", outcome.applicationFiles().size(),
				outcome.basePackage(), outcome.architectureFiles().size(), getOutputDirectory().get().getAsFile());
	}
}
