package org.triad.dsl.typing;

import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Port types of .arc models are Java type names, resolved loosely: a simple name is qualified by a
 * single-type import that ends in it, otherwise it stays simple. Two types are compatible if they
 * are the same name (a simple name matches a qualified name that ends in it), or by a small table
 * of known assignments (boxing, anything to Object).
 */
public final class ArcTypes {
	private static final Map<String, String> BOXES = Map.of("boolean", "Boolean", "int", "Integer", "long", "Long",
			"double", "Double", "float", "Float", "short", "Short", "byte", "Byte", "char", "Character");
	private static final Set<String> ANY = Set.of("Object", "java.lang.Object");

	private ArcTypes() {
	}

	/** The type name qualified by the single-type imports where one ends in its first segment. */
	public static String resolve(String typeName, List<String> imports) {
		String raw = erasure(typeName);
		if (raw.contains(".")) {
			return raw;
		}
		for (String i : imports) {
			if (!i.endsWith(".*") && i.endsWith("." + raw)) {
				return i;
			}
		}
		return raw;
	}

	/** The name without type arguments and array brackets. */
	public static String erasure(String typeName) {
		int lt = typeName.indexOf('<');
		String s = lt < 0 ? typeName : typeName.substring(0, lt);
		int br = s.indexOf('[');
		return (br < 0 ? s : s.substring(0, br)).trim();
	}

	public static String simpleName(String typeName) {
		String raw = erasure(typeName);
		return raw.substring(raw.lastIndexOf('.') + 1);
	}

	/** Whether a message of resolved type {@code from} may be sent to a port of resolved type {@code to}. */
	public static boolean isAssignable(String from, String to) {
		if (from.equals(to) || ANY.contains(to)) {
			return true;
		}
		if (!from.contains(".") || !to.contains(".")) {
			// a name that could not be qualified matches any qualified name that ends in it
			if (simpleName(from).equals(simpleName(to))) {
				return true;
			}
		}
		String boxedFrom = BOXES.getOrDefault(from, from);
		String boxedTo = BOXES.getOrDefault(to, to);
		return boxedFrom.equals(boxedTo) || boxedFrom.equals("java.lang." + boxedTo) || boxedTo.equals("java.lang." + boxedFrom);
	}

	private static final java.util.Map<String, java.util.Set<String>> KNOWN_SUPERTYPES = java.util.Map.of(
			"Number", java.util.Set.of("Integer", "Long", "Double", "Float", "Short", "Byte", "Number", "java.math.BigInteger", "java.math.BigDecimal"),
			"CharSequence", java.util.Set.of("String", "CharSequence", "StringBuilder"),
			"Comparable", java.util.Set.of("Integer", "Long", "Double", "Float", "Short", "Byte", "String", "Boolean", "Character"));

	/**
	 * Whether a type argument is within a type parameter's upper bound. Known by name for the java.lang
	 * bounds Number, CharSequence and Comparable (with or without {@code java.lang.}); any other bound is
	 * left to the Java compiler.
	 */
	public static boolean withinBound(String argument, String bound) {
		String b = erasure(bound).replaceFirst("^java\\.lang\\.", "");
		String a = erasure(argument).replaceFirst("^java\\.lang\\.", "");
		if (b.equals("Object") || a.equals(b)) {
			return true;
		}
		java.util.Set<String> known = KNOWN_SUPERTYPES.get(b);
		if (known == null) {
			return true;
		}
		boolean knownArgument = KNOWN_SUPERTYPES.values().stream().anyMatch(set -> set.contains(a)) || a.equals("Boolean") || a.equals("Character");
		return !knownArgument || known.contains(a);
	}

	/** Whether a name is a public class of java.lang ({@code Math}, {@code Long}). */
	public static boolean isJavaLangClass(String name) {
		if (!name.matches("[A-Z][A-Za-z0-9_]*")) {
			return false;
		}
		try {
			Class.forName("java.lang." + name, false, ArcTypes.class.getClassLoader());
			return true;
		} catch (ClassNotFoundException | LinkageError e) {
			return false;
		}
	}
}
