package org.triad.cli;

/** The one line an unexpected failure of a command is reported as, instead of a stack trace. */
final class FailureMessage {
	private FailureMessage() {
	}

	/** The innermost message that says something, else the failure's type. */
	static String of(Throwable e) {
		Throwable t = e;
		while (t.getCause() != null && t.getCause() != t && (t.getMessage() == null || t instanceof RuntimeException && t.getCause() != null)) {
			t = t.getCause();
		}
		return t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
	}
}
