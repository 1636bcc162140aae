package org.triad.dsl.app;

import java.nio.file.Path;

/**
 * One finding about a model file, printed as {@code path:line:col: error|warning CODE: message}
 * (line and column 1-based).
 */
public record ModelDiagnostic(Path file, int line, int column, Severity severity, String code, String message)
		implements Comparable<ModelDiagnostic> {
	public enum Severity {
		ERROR, WARNING;

		public String label() {
			return name().toLowerCase();
		}
	}

	/** The diagnostic as one line, with the file shown relative to {@code base}. */
	public String format(Path base) {
		Path shown = file.isAbsolute() && base != null && file.startsWith(base) ? base.relativize(file) : file;
		return shown + ":" + line + ":" + column + ": " + severity.label() + " " + code + ": " + message;
	}

	public boolean isError() {
		return severity == Severity.ERROR;
	}

	@Override
	public int compareTo(ModelDiagnostic o) {
		int c = file.toString().compareTo(o.file.toString());
		if (c == 0) {
			c = Integer.compare(line, o.line);
		}
		if (c == 0) {
			c = Integer.compare(column, o.column);
		}
		return c != 0 ? c : code.compareTo(o.code);
	}
}
