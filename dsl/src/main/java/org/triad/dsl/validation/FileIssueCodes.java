package org.triad.dsl.validation;

/**
 * Stable codes of findings about a model file as a whole, before any of its text is read
 * ({@link org.triad.dsl.app.ApplicationAssembler}).
 */
public final class FileIssueCodes {
	private FileIssueCodes() {
	}

	/**
	 * A model file larger than Triad reads ({@link org.triad.dsl.app.ApplicationAssembler#MAX_MODEL_FILE_BYTES}):
	 * the check stops there, at {@code path:1:1}, instead of spending minutes and gigabytes on it.
	 */
	public static final String TOO_LARGE = "file.too-large";
}
