package org.triad.generator.arc;

import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.emf.common.util.URI;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;

/**
 * Where hand-written Java lives, to decide per component whether the generator writes the class of
 * the component's name or its TOP class for a hand-written subclass (MontiArc's TOP pattern).
 */
@FunctionalInterface
public interface HandwrittenCode {
	/** Whether a hand-written class of this qualified name exists. */
	boolean has(String qualifiedClassName);

	HandwrittenCode NONE = name -> false;

	/** Hand-written classes below a Java source folder. */
	static HandwrittenCode in(Path sourceRoot) {
		return name -> Files.isRegularFile(sourceRoot.resolve(name.replace('.', '/') + ".java"));
	}

	/**
	 * The Maven convention: models of package {@code a.b} in {@code <project>/src/main/arc/a/b/X.arc},
	 * hand-written Java in {@code <project>/src/main/java}. Models elsewhere (in memory, in a jar) have none.
	 */
	static HandwrittenCode besideModelsOf(ComponentType c) {
		URI uri = c.eResource() == null ? null : c.eResource().getURI();
		if (uri == null || !uri.isFile()) {
			return NONE;
		}
		Path root = Path.of(uri.toFileString()).toAbsolutePath().getParent();
		String pkg = ArcModels.packageName(c);
		if (!pkg.isEmpty()) {
			for (int i = pkg.split("\\.").length; i > 0 && root != null; i--) {
				root = root.getParent();
			}
		}
		if (root == null || root.getFileName() == null || !root.getFileName().toString().equals("arc") || root.getParent() == null) {
			return NONE;
		}
		return in(root.resolveSibling("java"));
	}
}
