package org.triad.runtime.schema;

/**
 * One effect of an action: {@code call} made to hold or not ({@code value} null, Boolean property),
 * or assigned {@code value} (other properties; the previous value no longer holds).
 */
public record Effect(Expr.Call call, boolean holds, Expr value) {
	public boolean isAssignment() {
		return value != null;
	}
}
