package org.triad.gradle;

import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.DirectoryProperty;
import org.gradle.api.provider.Property;

/**
 * The {@code triad { }} block of a models project. Defaults: {@code src/main/models} and
 * {@code src/main/arc}, the application's package {@code generated.<application>}.
 */
public abstract class TriadModelsExtension {
	/** The application's models (.cd .actor .goal .task .state). */
	public abstract DirectoryProperty getModels();

	/** The application's architecture (.arc); nothing is generated from it when the folder is absent. */
	public abstract DirectoryProperty getArchitecture();

	/** Folders of .arc models the architecture uses without generating them, e.g. RefArc's {@code refarc/src/main/arc}. */
	public abstract ConfigurableFileCollection getArchitectureLibraries();

	/** The base Java package of the architecture's components (default: none, the .arc packages as they are). */
	public abstract Property<String> getArchitecturePackage();

	/** The application's Java package (default: {@code generated.<application>}). */
	public abstract Property<String> getBasePackage();
}
