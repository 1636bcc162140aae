package org.triad.dsl.typing;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.BinaryOperator;
import org.triad.dsl.triad.BooleanLiteral;
import org.triad.dsl.triad.DecimalLiteral;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.DomainTypeRef;
import org.triad.dsl.triad.MemberRef;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.IntLiteral;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.PrimitiveTypeRef;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.StringLiteral;
import org.triad.dsl.triad.TypeRef;
import org.triad.dsl.triad.ValueRef;

/** Computes and compares the types of Triad expressions; subtypes are assignable to supertypes. */
public final class TriadTypeSystem {
	private TriadTypeSystem() {
	}

	public static TriadType typeOf(TypeRef ref) {
		if (ref instanceof PrimitiveTypeRef p) {
			return switch (p.getKind()) {
				case BOOLEAN -> TriadType.BOOLEAN;
				case INT -> TriadType.INT;
				case DOUBLE -> TriadType.DOUBLE;
				case STRING -> TriadType.STRING;
			};
		}
		if (ref instanceof DomainTypeRef d) {
			return TriadType.of(d.getType());
		}
		return TriadType.UNKNOWN;
	}

	public static TriadType typeOf(Expression e) {
		if (e instanceof BinaryExpression b && isArithmetic(b.getOperator())) {
			TriadType l = typeOf(b.getLeft());
			TriadType r = typeOf(b.getRight());
			if (!l.isNumeric() || !r.isNumeric()) {
				return TriadType.UNKNOWN; // reported once, at the operator (expr.not-numeric)
			}
			// '/' divides numbers as they are measured (7 / 2 is 3.5), so it is a double
			return l.kind() == TriadType.Kind.INT && r.kind() == TriadType.Kind.INT && b.getOperator() != BinaryOperator.DIVIDE
					? TriadType.INT : TriadType.DOUBLE;
		}
		if (e instanceof org.triad.dsl.triad.NegationExpression n) {
			TriadType t = typeOf(n.getOperand());
			return t.isNumeric() ? t : TriadType.UNKNOWN; // a non-number is reported once, at the '-' (expr.not-numeric)
		}
		if (e instanceof BinaryExpression || e instanceof NotExpression || e instanceof BooleanLiteral) {
			return TriadType.BOOLEAN;
		}
		if (e instanceof IntLiteral) {
			return TriadType.INT;
		}
		if (e instanceof DecimalLiteral) {
			return TriadType.DOUBLE;
		}
		if (e instanceof StringLiteral) {
			return TriadType.STRING;
		}
		if (e instanceof MemberRef r) {
			if (r.getOwner() instanceof Enumeration en) {
				return TriadType.of(en);
			}
			return r.getMember() instanceof Attribute a && !a.eIsProxy() ? typeOf(a.getType()) : TriadType.UNKNOWN;
		}
		if (e instanceof PropertyCall c) {
			Property p = c.getProperty();
			return p == null || p.eIsProxy() ? TriadType.UNKNOWN : typeOf(p.getType());
		}
		if (e instanceof ValueRef v) {
			return typeOf(v.getValue());
		}
		return TriadType.UNKNOWN;
	}

	/** The type of a parameter or of a situation's object. */
	public static TriadType typeOf(org.triad.dsl.triad.Value v) {
		if (v instanceof Parameter p) {
			return typeOf(p.getType());
		}
		if (v instanceof SituationObject o && o.eContainer() instanceof ObjectDeclaration d) {
			return TriadType.of(d.getType());
		}
		return TriadType.UNKNOWN;
	}

	/** Whether an expression is arithmetic: {@code + - * /} on two numbers, or a number negated ({@code -x}). */
	public static boolean isArithmetic(Expression e) {
		return e instanceof BinaryExpression b && isArithmetic(b.getOperator()) || e instanceof org.triad.dsl.triad.NegationExpression;
	}

	/** Whether an operator is arithmetic ({@code + - * /}) rather than a comparison or connective. */
	public static boolean isArithmetic(BinaryOperator op) {
		return op == BinaryOperator.PLUS || op == BinaryOperator.MINUS || op == BinaryOperator.TIMES || op == BinaryOperator.DIVIDE;
	}

	/** Whether a value of type {@code source} may be used where {@code target} is expected. */
	public static boolean isAssignable(TriadType target, TriadType source) {
		if (target.isUnknown() || source.isUnknown()) {
			return true;
		}
		if (target.kind() == TriadType.Kind.DOUBLE && source.kind() == TriadType.Kind.INT) {
			return true;
		}
		if (target.kind() != source.kind()) {
			return false;
		}
		if (target.kind() == TriadType.Kind.CLASS) {
			// a class whose superclass did not resolve may be anything (its unknown superclass is reported once)
			return isSubclass(source.domainClass(), target.domainClass()) || hasUnknownAncestry(source.domainClass());
		}
		return target.domainType() == source.domainType();
	}

	/** Whether two values can be compared with {@code ==}: one type is assignable to the other. */
	public static boolean isComparable(TriadType a, TriadType b) {
		return isAssignable(a, b) || isAssignable(b, a);
	}

	public static boolean isSubclass(DomainClass sub, DomainClass sup) {
		for (DomainClass c : superClassesAndSelf(sub)) {
			if (c == sup) {
				return true;
			}
		}
		return false;
	}

	/** Whether some superclass of {@code c} is an unresolved reference. */
	public static boolean hasUnknownAncestry(DomainClass c) {
		List<DomainClass> chain = superClassesAndSelf(c);
		if (chain.isEmpty()) {
			return c != null;
		}
		DomainClass top = chain.get(chain.size() - 1).getSuperType();
		return top != null && top.eIsProxy();
	}

	/** The class and its superclasses, nearest first; stops at a cycle or an unresolved superclass. */
	public static List<DomainClass> superClassesAndSelf(DomainClass c) {
		Set<DomainClass> seen = new LinkedHashSet<>();
		DomainClass current = c;
		while (current != null && !current.eIsProxy() && seen.add(current)) {
			current = current.getSuperType();
		}
		return new ArrayList<>(seen);
	}

	/** The attributes of a class including inherited ones, superclasses first. */
	public static List<Attribute> allAttributes(DomainClass c) {
		List<DomainClass> chain = superClassesAndSelf(c);
		List<Attribute> result = new ArrayList<>();
		for (int i = chain.size() - 1; i >= 0; i--) {
			result.addAll(chain.get(i).getAttributes());
		}
		return result;
	}
}
