package org.triad.dsl.semantics;

import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.PropertyCall;

/**
 * One effect of an action's postcondition: a Boolean property made to hold ({@code p(args)}) or
 * not to hold ({@code !p(args)}), or a property assigned a value ({@code f(args) == v}), where the
 * previous value no longer holds.
 *
 * @param call     the affected property with its arguments
 * @param holds    for a Boolean property, whether it holds afterwards (true for assignments)
 * @param value    the assigned value of a non-Boolean property, or null for a Boolean one
 */
public record PostconditionEffect(PropertyCall call, boolean holds, Expression value) {
	public boolean isAssignment() {
		return value != null;
	}
}
