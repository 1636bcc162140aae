package org.triad.runtime.app;

/** A literal of an enumeration of the class diagram, independent of the generated Java enum. */
public record EnumValue(String enumeration, String literal) {
	@Override
	public String toString() {
		return enumeration + "." + literal;
	}
}
