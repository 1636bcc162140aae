package org.triad.dsl.arc.generator;

import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.Set;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.resource.ResourceSet;
import org.triad.dsl.arc.ArcModel;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.semantics.ArcModels;

/**
 * The Java imports of a generated class: the runtime types it uses plus the model's imports of Java
 * types. Imports of .arc components or packages are left out, since generated code names
 * component classes by their Java names.
 */
final class JavaImports {
	private JavaImports() {
	}

	static Set<String> of(ComponentType c, Set<String> runtimeTypes) {
		Set<String> arcPackages = new HashSet<>();
		Set<String> components = new HashSet<>();
		ResourceSet rs = c.eResource() == null ? null : c.eResource().getResourceSet();
		if (rs != null) {
			for (Resource r : rs.getResources()) {
				if (!r.getContents().isEmpty() && r.getContents().get(0) instanceof ArcModel m && m.getComponent() != null) {
					arcPackages.add(ArcModels.packageName(m));
					components.add(ArcModels.qualifiedName(m.getComponent()));
				}
			}
		}
		Set<String> imports = new LinkedHashSet<>();
		for (String t : runtimeTypes) {
			imports.add(ArcNames.RUNTIME_PACKAGE + "." + t);
		}
		for (String i : ArcModels.imports(c)) {
			boolean wildcard = i.endsWith(".*");
			String target = wildcard ? i.substring(0, i.length() - 2) : i;
			if (!(wildcard ? arcPackages.contains(target) : components.contains(target))) {
				imports.add(i);
			}
		}
		return imports;
	}
}
