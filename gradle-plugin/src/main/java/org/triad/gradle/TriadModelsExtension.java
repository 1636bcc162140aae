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

	/**
	 * No longer has an effect, and setting it fails the build: an .arc model's package is its Java
	 * package. Kept so that builds which still set it get {@link TriadModelsPlugin#ARCHITECTURE_PACKAGE_REMOVED}
	 * rather than an unknown-property error.
	 *
	 * @deprecated write the package into the .arc models instead
	 */
	@Deprecated
	public abstract Property<String> getArchitecturePackage();

	/** The application's Java package (default: {@code generated.<application>}). */
	public abstract Property<String> getBasePackage();
}
