package org.triad.dsl.app;

import java.nio.file.Path;
import java.util.List;

import org.eclipse.xtext.resource.XtextResourceSet;
import org.triad.dsl.triad.Application;

/**
 * The models below one folder, linked and checked together.
 *
 * @param root        the folder
 * @param resourceSet the loaded resources
 * @param application the application's elements, as far as they exist
 * @param diagnostics every error and warning, sorted by file and position
 */
public record LoadedApplication(Path root, XtextResourceSet resourceSet, Application application, List<ModelDiagnostic> diagnostics) {
	public boolean hasErrors() {
		return diagnostics.stream().anyMatch(ModelDiagnostic::isError);
	}
}
