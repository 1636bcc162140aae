package org.triad.dsl.semantics;

import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.DecimalLiteral;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.IntLiteral;
import org.triad.dsl.typing.TriadTypeSystem;

/**
 * The value of arithmetic on literals ({@code 2 * 3}, {@code 10 / (5 - 5)}), as the runtime computes it,
 * so that a division by zero or an overflow in a model is a finding at check time rather than a fault
 * while planning. An {@code int} result past the range of {@code int} overflows; a {@code double} one
 * that is not finite does.
 */
public final class ConstantArithmetic {
	private ConstantArithmetic() {
	}

	/** What folding gave: a value, or why there is none (null when the expression is not constant). */
	public record Folded(Double value, boolean divisionByZero, boolean overflow, boolean integral) {
		static final Folded NOT_CONSTANT = new Folded(null, false, false, false);

		Folded(Double value, boolean divisionByZero, boolean overflow) {
			this(value, divisionByZero, overflow, false);
		}

		public boolean isConstant() {
			return value != null;
		}
	}

	public static Folded fold(Expression e) {
		if (e instanceof IntLiteral l) {
			return new Folded((double) l.getValue(), false, false, true);
		}
		if (e instanceof DecimalLiteral l) {
			return new Folded(l.getValue(), false, false);
		}
		if (e instanceof org.triad.dsl.triad.NegationExpression n) {
			Folded f = fold(n.getOperand());
			return f.isConstant() ? new Folded(-f.value(), false, false, f.integral()) : f;
		}
		if (!(e instanceof BinaryExpression b) || !TriadTypeSystem.isArithmetic(b.getOperator())) {
			return Folded.NOT_CONSTANT;
		}
		Folded l = fold(b.getLeft());
		Folded r = fold(b.getRight());
		if (!l.isConstant() || !r.isConstant()) {
			return Folded.NOT_CONSTANT;
		}
		double x = l.value();
		double y = r.value();
		// from the operands, not TriadTypeSystem.typeOf: that recurses, and folding every node of a long chain would be cubic
		boolean integral = l.integral() && r.integral() && b.getOperator() != org.triad.dsl.triad.BinaryOperator.DIVIDE;
		double v = switch (b.getOperator()) {
			case PLUS -> x + y;
			case MINUS -> x - y;
			case TIMES -> x * y;
			default -> y == 0 ? Double.NaN : x / y;
		};
		if (b.getOperator() == org.triad.dsl.triad.BinaryOperator.DIVIDE && y == 0) {
			return new Folded(null, true, false);
		}
		boolean overflow = integral ? v > Integer.MAX_VALUE || v < Integer.MIN_VALUE : Double.isInfinite(v) || Double.isNaN(v);
		return overflow ? new Folded(null, false, true) : new Folded(v, false, false, integral);
	}
}
