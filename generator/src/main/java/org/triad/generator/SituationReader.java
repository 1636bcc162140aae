package org.triad.generator;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.dsl.triad.AttributeAssignment;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.SituationObject;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GenericObject;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.Evaluator;
import org.triad.runtime.schema.Expr;

/** Reads a checked situation ({@code .state}) as a runtime {@link State} of generic objects. */
public final class SituationReader {
	private SituationReader() {
	}

	public static State read(Situation situation, AppSchema schema) {
		State.Builder b = State.builder();
		for (ObjectDeclaration d : situation.getDeclarations()) {
			for (SituationObject o : d.getObjects()) {
				Map<String, Object> attributes = new LinkedHashMap<>();
				for (AttributeAssignment a : o.getAssignments()) {
					attributes.put(a.getAttribute().getName(), literal(SchemaBuilder.expr(a.getValue())));
				}
				b.object(new GenericObject(o.getName(), d.getType().getName(), attributes));
			}
		}
		State objects = b.build();
		Evaluator evaluator = new Evaluator(schema);
		for (Expression fact : situation.getFacts()) {
			if (fact instanceof PropertyCall call) {
				b.fact(evaluator.atom((Expr.Call) SchemaBuilder.expr(call), objects, Map.of()));
			} else if (fact instanceof BinaryExpression eq && eq.getLeft() instanceof PropertyCall call) {
				Atom atom = evaluator.atom((Expr.Call) SchemaBuilder.expr(call), objects, Map.of());
				b.value(atom, evaluator.eval(SchemaBuilder.expr(eq.getRight()), objects, Map.of()));
			}
		}
		return b.build();
	}

	private static Object literal(Expr e) {
		return e instanceof Expr.Lit l ? l.value() : e instanceof Expr.EnumLit l ? new org.triad.runtime.app.EnumValue(l.enumeration(), l.literal()) : null;
	}

}
