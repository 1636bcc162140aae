package org.triad.runtime.schema;

/** A model construct, state or goal that the PDDL translation cannot express (the message says what). */
public class PddlTranslationException extends RuntimeException {
	private static final long serialVersionUID = 1L;

	public PddlTranslationException(String message) {
		super(message);
	}
}
