package org.triad.dsl.typing;

import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainType;
import org.triad.dsl.triad.Enumeration;

/**
 * The type of an expression: a built-in type, a class or enumeration of the class diagram, or
 * unknown where a reference did not resolve (unknown is compatible with everything, so one
 * unresolved name yields one diagnostic, not a cascade).
 */
public record TriadType(Kind kind, DomainType domainType) {
	public enum Kind { BOOLEAN, INT, DOUBLE, STRING, CLASS, ENUM, UNKNOWN }

	public static final TriadType BOOLEAN = new TriadType(Kind.BOOLEAN, null);
	public static final TriadType INT = new TriadType(Kind.INT, null);
	public static final TriadType DOUBLE = new TriadType(Kind.DOUBLE, null);
	public static final TriadType STRING = new TriadType(Kind.STRING, null);
	public static final TriadType UNKNOWN = new TriadType(Kind.UNKNOWN, null);

	public static TriadType of(DomainType type) {
		if (type == null || type.eIsProxy()) {
			return UNKNOWN;
		}
		return new TriadType(type instanceof Enumeration ? Kind.ENUM : Kind.CLASS, type);
	}

	public boolean isUnknown() {
		return kind == Kind.UNKNOWN;
	}

	public boolean isBoolean() {
		return kind == Kind.BOOLEAN || isUnknown();
	}

	public boolean isNumeric() {
		return kind == Kind.INT || kind == Kind.DOUBLE || isUnknown();
	}

	public DomainClass domainClass() {
		return domainType instanceof DomainClass c ? c : null;
	}

	/** The name a model author writes for this type. */
	public String display() {
		return switch (kind) {
			case BOOLEAN -> "boolean";
			case INT -> "int";
			case DOUBLE -> "double";
			case STRING -> "String";
			case CLASS, ENUM -> domainType.getName();
			case UNKNOWN -> "unknown";
		};
	}

	/**
	 * The name shown next to {@code other} in a message: qualified by its class diagram when both
	 * are different types with the same simple name ("Depot.Place" and "Shop.Place").
	 */
	public String displayAgainst(TriadType other) {
		if (domainType != null && other != null && !equals(other) && display().equals(other.display())
				&& domainType.eContainer() instanceof org.triad.dsl.triad.ClassDiagram cd) {
			return cd.getName() + "." + display();
		}
		return display();
	}

	@Override
	public boolean equals(Object o) {
		return o instanceof TriadType t && t.kind == kind && t.domainType == domainType;
	}

	@Override
	public int hashCode() {
		return kind.hashCode() * 31 + System.identityHashCode(domainType);
	}

	@Override
	public String toString() {
		return display();
	}
}
