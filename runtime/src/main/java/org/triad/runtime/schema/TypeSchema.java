package org.triad.runtime.schema;

import java.util.List;

/** A class (with its superclass, or null) or an enumeration (with its literals) of the class diagram. */
public record TypeSchema(String name, String superType, boolean isAbstract, List<String> literals, boolean isEnum) {
	public TypeSchema {
		literals = List.copyOf(literals);
	}

	public static TypeSchema ofClass(String name, String superType, boolean isAbstract) {
		return new TypeSchema(name, superType, isAbstract, List.of(), false);
	}

	public static TypeSchema ofEnum(String name, List<String> literals) {
		return new TypeSchema(name, null, false, literals, true);
	}
}
