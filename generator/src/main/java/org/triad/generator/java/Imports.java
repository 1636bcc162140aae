package org.triad.generator.java;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

/**
 * The imports of one generated compilation unit. A type is referred to by its simple name when that
 * is unambiguous (imported, same package, or {@code java.lang} not shadowed), otherwise by its
 * qualified name, so model names that clash with each other or with Java's still compile.
 */
public final class Imports {
	private final String ownPackage;
	private final String ownName;
	private final Set<String> samePackage;
	/** Simple name to the qualified name it stands for in this unit. */
	private final Map<String, String> simpleNames = new HashMap<>();
	private final Set<String> imports = new TreeSet<>();

	Imports(String ownPackage, String ownName, Set<String> samePackage) {
		this.ownPackage = ownPackage;
		this.ownName = ownName;
		this.samePackage = samePackage;
		simpleNames.put(ownName, ownPackage + "." + ownName);
	}

	/** How to write a type here; primitives and unqualified names come back unchanged. */
	public String ref(String qualified) {
		int dot = qualified.lastIndexOf('.');
		if (dot < 0) {
			return qualified;
		}
		String pkg = qualified.substring(0, dot);
		String simple = qualified.substring(dot + 1);
		String taken = simpleNames.get(simple);
		if (taken != null) {
			return taken.equals(qualified) ? simple : qualified;
		}
		if (pkg.equals(ownPackage)) {
			simpleNames.put(simple, qualified);
			return simple;
		}
		if (samePackage.contains(simple) || simple.equals(ownName)) {
			return qualified;
		}
		simpleNames.put(simple, qualified);
		if (!pkg.equals("java.lang")) {
			imports.add(qualified);
		}
		return simple;
	}

	/** The import declarations, one a line; call after the body has been generated. */
	public String declarations() {
		return imports.stream().map(i -> "import " + i + ";").collect(Collectors.joining("\n"));
	}
}
