package org.triad.generator.arc;

import java.util.LinkedHashSet;
import java.util.Set;

import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;

/**
 * The Java imports of a generated class: the runtime types it uses plus the model's imports, which
 * are valid Java as they stand because a component's Java package is its .arc package and its class
 * has its name.
 */
final class JavaImports {
	private JavaImports() {
	}

	static Set<String> of(ComponentType c, Set<String> runtimeTypes) {
		return of(c, runtimeTypes, DataTypes.NONE);
	}

	/** With imports of class-diagram types ({@code p.Diagram.T}, {@code p.Diagram.*}) as their Java package's ({@code p.T}, {@code p.*}). */
	static Set<String> of(ComponentType c, Set<String> runtimeTypes, DataTypes dataTypes) {
		Set<String> imports = new LinkedHashSet<>();
		for (String t : runtimeTypes) {
			imports.add(ArcNames.RUNTIME_PACKAGE + "." + t);
		}
		String own = ArcModels.packageName(c);
		for (String i : ArcModels.imports(c)) {
			if (!i.equals(own + ".*")) {
				String java = dataTypes.javaImport(i);
				if (!java.equals(own + ".*")) {
					imports.add(java);
				}
			}
		}
		return imports;
	}
}
