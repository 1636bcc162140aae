package org.triad.dsl.parser;

import org.antlr.runtime.IntStream;
import org.antlr.runtime.RecognitionException;

/** Raised inside a parser rule where an expression passes one of the {@link ExpressionLimits}; located at that token. */
public final class ExpressionTooDeepException extends RecognitionException {
	private static final long serialVersionUID = 1L;

	private final String reason;

	ExpressionTooDeepException(IntStream input, String reason) {
		super(input);
		this.reason = reason;
	}

	public String reason() {
		return reason;
	}
}
