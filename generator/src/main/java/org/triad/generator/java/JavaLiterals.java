package org.triad.generator.java;

/** Java source literals for model values. */
public final class JavaLiterals {
	private JavaLiterals() {
	}

	/** A Java string literal with the characters that need it escaped. */
	public static String string(String s) {
		if (s == null) {
			return "null";
		}
		StringBuilder b = new StringBuilder("\"");
		for (char c : s.toCharArray()) {
			switch (c) {
				case '"' -> b.append("\\\"");
				case '\\' -> b.append("\\\\");
				case '\n' -> b.append("\\n");
				case '\r' -> b.append("\\r");
				case '\t' -> b.append("\\t");
				default -> {
					if (c < 0x20 || c > 0x7e) {
						b.append(String.format("\\u%04x", (int) c));
					} else {
						b.append(c);
					}
				}
			}
		}
		return b.append('"').toString();
	}

	/** A literal of a runtime value: Boolean, Integer, Double or String. */
	public static String value(Object v) {
		if (v instanceof String s) {
			return string(s);
		}
		if (v instanceof Double d) {
			return Double.toString(d) + "d";
		}
		if (v instanceof Integer || v instanceof Boolean) {
			return String.valueOf(v);
		}
		throw new IllegalArgumentException("not a literal of the Triad languages: " + v);
	}
}
