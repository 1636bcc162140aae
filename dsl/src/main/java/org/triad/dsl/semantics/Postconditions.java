package org.triad.dsl.semantics;

import java.util.ArrayList;
import java.util.List;

import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.BinaryOperator;
import org.triad.dsl.triad.BooleanLiteral;
import org.triad.dsl.triad.MemberRef;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.IntLiteral;
import org.triad.dsl.triad.DecimalLiteral;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.StringLiteral;
import org.triad.dsl.triad.ValueRef;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * Reads a postcondition as a conjunction of {@link PostconditionEffect}s, the only form the planner and the
 * dry-run actors can apply. Used by the validator (which reports what does not fit) and by the
 * generators and runtime translations (which rely on it fitting).
 */
public final class Postconditions {
	private Postconditions() {
	}

	/** A part of a postcondition that is not an effect, with the reason. */
	public record Problem(Expression expression, String message, boolean badValue) {
		Problem(Expression expression, String message) {
			this(expression, message, false);
		}
	}

	/** The effects and the problems of a postcondition ({@code null} means no effects). */
	public record Analysis(List<PostconditionEffect> effects, List<Problem> problems) {
	}

	public static Analysis analyse(Expression post) {
		List<PostconditionEffect> effects = new ArrayList<>();
		List<Problem> problems = new ArrayList<>();
		if (post != null && !(post instanceof BooleanLiteral b && b.isValue())) {
			collect(post, effects, problems);
		}
		return new Analysis(effects, problems);
	}

	/** The conjuncts of an expression ({@code a && b && c} gives a, b, c). */
	public static List<Expression> conjuncts(Expression e) {
		List<Expression> result = new ArrayList<>();
		addConjuncts(e, result);
		return result;
	}

	private static void addConjuncts(Expression e, List<Expression> into) {
		if (e instanceof BinaryExpression b && b.getOperator() == BinaryOperator.AND) {
			addConjuncts(b.getLeft(), into);
			addConjuncts(b.getRight(), into);
		} else if (e != null) {
			into.add(e);
		}
	}

	private static void collect(Expression post, List<PostconditionEffect> effects, List<Problem> problems) {
		for (Expression c : conjuncts(post)) {
			if (c instanceof PropertyCall call) {
				if (isBoolean(call)) {
					effects.add(new PostconditionEffect(call, true, null));
				} else {
					problems.add(new Problem(c, "effect on non-boolean property '" + name(call) + "' must assign a value: '"
							+ name(call) + "(...) == value'"));
				}
			} else if (c instanceof NotExpression n && n.getOperand() instanceof PropertyCall call) {
				if (isBoolean(call)) {
					effects.add(new PostconditionEffect(call, false, null));
				} else {
					problems.add(new Problem(c, "'!' applies to boolean properties only, not to '" + name(call) + "'"));
				}
			} else if (c instanceof BinaryExpression b && b.getOperator() == BinaryOperator.EQ && b.getLeft() instanceof PropertyCall call) {
				if (isStrictlyBoolean(call)) {
					problems.add(new Problem(c, "write '" + name(call) + "(...)' or '!" + name(call)
							+ "(...)' for a boolean property instead of comparing it"));
				} else if (!isValue(b.getRight()) && !(isNumber(call) && isArithmeticValue(b.getRight()))) {
					problems.add(new Problem(b.getRight(), "the value assigned to '" + name(call)
							+ "' must be a parameter, a literal or an enumeration literal"
							+ (isNumber(call) ? ", or arithmetic on the values before the action, e.g. '" + name(call) + "()@pre - 5'" : ""), true));
				} else {
					effects.add(new PostconditionEffect(call, true, b.getRight()));
				}
			} else {
				problems.add(new Problem(c, "a postcondition is a conjunction (&&) of effects: 'p(...)', '!p(...)' or 'f(...) == value'"));
			}
		}
	}

	/** Whether an expression is a plain value: a parameter or object, a literal (a negative number too), or an enumeration literal. */
	public static boolean isValue(Expression e) {
		return e instanceof ValueRef || e instanceof IntLiteral || e instanceof DecimalLiteral || e instanceof StringLiteral
				|| e instanceof BooleanLiteral || e instanceof MemberRef m && m.getOwner() instanceof org.triad.dsl.triad.Enumeration
				|| e instanceof org.triad.dsl.triad.NegationExpression n && (n.getOperand() instanceof IntLiteral || n.getOperand() instanceof DecimalLiteral);
	}

	/** A number computed from values before the action: arithmetic, or a property read ({@code p()@pre}). */
	public static boolean isArithmeticValue(Expression e) {
		return e instanceof PropertyCall || TriadTypeSystem.isArithmetic(e);
	}

	private static boolean isNumber(PropertyCall call) {
		TriadType t = TriadTypeSystem.typeOf(call);
		return t.kind() == TriadType.Kind.INT || t.kind() == TriadType.Kind.DOUBLE;
	}

	/** Boolean, or unknown because the property did not resolve (reported once, by the linker). */
	private static boolean isBoolean(PropertyCall call) {
		return TriadTypeSystem.typeOf(call).isBoolean();
	}

	private static boolean isStrictlyBoolean(PropertyCall call) {
		return TriadTypeSystem.typeOf(call).kind() == TriadType.Kind.BOOLEAN;
	}

	private static String name(PropertyCall call) {
		return call.getProperty() == null || call.getProperty().eIsProxy() ? "?" : call.getProperty().getName();
	}
}
