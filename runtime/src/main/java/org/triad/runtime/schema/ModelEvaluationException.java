package org.triad.runtime.schema;

/** A model expression that cannot be evaluated in a state (unbound name, property without value in a comparison of numbers, ...). */
public class ModelEvaluationException extends RuntimeException {
	private static final long serialVersionUID = 1L;

	public ModelEvaluationException(String message) {
		super(message);
	}
}
