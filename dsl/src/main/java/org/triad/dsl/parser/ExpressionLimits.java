package org.triad.dsl.parser;

/**
 * How deep an expression may be. The parser stops at these limits with the diagnostic
 * {@code expr.too-deep} instead of letting the recursion of parsing, linking, checking, generating
 * or planning overflow the stack, and so that every pass over the model stays linear in its size.
 */
public final class ExpressionLimits {
	private ExpressionLimits() {
	}

	/** Levels of parentheses, negations and call arguments an expression may nest. */
	public static final int MAX_NESTING = 100;

	/**
	 * How many operators deep an expression may be: each operator of a chain such as
	 * {@code a && b && c} is one level (chains are left-nested trees), as are a negation and a call
	 * with arguments below it. Checked where an operator is added on top of its left operand, so
	 * with {@link #MAX_NESTING} every expression tree is at most {@code MAX_DEPTH + 3 * MAX_NESTING}
	 * levels deep.
	 */
	public static final int MAX_DEPTH = 1000;
}
