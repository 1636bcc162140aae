package org.triad.generator.arc;

/** Model comments carried into generated javadoc. */
final class JavaDoc {
	private JavaDoc() {
	}

	/** Lines of a javadoc paragraph ({@code " *\n * <p>..."}), "" for no text; comment terminators are defused. */
	static String paragraph(String text) {
		if (text == null || text.isBlank()) {
			return "";
		}
		StringBuilder b = new StringBuilder(" *\n");
		boolean first = true;
		for (String line : text.replace("*/", "*&#47;").split("\\R")) {
			b.append(" * ").append(first ? "<p>" : "").append(line).append('\n');
			first = false;
		}
		return b.toString().replace(" * \n", " *\n");
	}
}
