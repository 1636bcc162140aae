package org.triad.generator;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.dsl.triad.AttributeAssignment;
import org.triad.dsl.triad.BinaryExpression;
import org.triad.dsl.triad.Expression;
import org.triad.dsl.triad.NotExpression;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.PropertyCall;
import org.triad.dsl.triad.Situation;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.semantics.SituationLineage;
import org.triad.dsl.typing.TriadType;
import org.triad.dsl.typing.TriadTypeSystem;
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

	/**
	 * The situation's objects and facts; for {@code state B extends A}, A's first, then B's, whose values replace
	 * A's and whose {@code !A.p(x)} retract A's facts.
	 */
	public static State read(Situation situation, AppSchema schema) {
		List<Situation> order = SituationLineage.applicationOrder(situation);
		State.Builder b = State.builder();
		for (Situation s : order) {
			for (ObjectDeclaration d : s.getDeclarations()) {
				for (SituationObject o : d.getObjects()) {
					Map<String, Object> attributes = new LinkedHashMap<>();
					for (AttributeAssignment a : o.getAssignments()) {
						Object value = literal(SchemaBuilder.expr(a.getValue()));
						attributes.put(a.getAttribute().getName(),
								TriadTypeSystem.typeOf(a.getAttribute().getType()).kind() == TriadType.Kind.DOUBLE ? asDouble(value) : value);
					}
					b.object(new GenericObject(o.getName(), d.getType().getName(), attributes));
				}
			}
		}
		State objects = b.build();
		Evaluator evaluator = new Evaluator(schema);
		for (Situation s : order) {
			for (Expression fact : s.getFacts()) {
				if (fact instanceof PropertyCall call) {
					b.fact(evaluator.atom((Expr.Call) SchemaBuilder.expr(call), objects, Map.of()));
				} else if (fact instanceof NotExpression not && not.getOperand() instanceof PropertyCall call) {
					b.retract(evaluator.atom((Expr.Call) SchemaBuilder.expr(call), objects, Map.of()));
				} else if (fact instanceof BinaryExpression eq && eq.getLeft() instanceof PropertyCall call) {
					Expr.Call c = (Expr.Call) SchemaBuilder.expr(call);
					Atom atom = evaluator.atom(c, objects, Map.of());
					Object value = evaluator.eval(SchemaBuilder.expr(eq.getRight()), objects, Map.of());
					boolean isDouble = schema.property(c.actor(), c.property()).map(p -> "double".equals(p.type())).orElse(false);
					b.value(atom, isDouble ? asDouble(value) : value);
				}
			}
		}
		return b.build();
	}

	/** An int literal where a double is expected is the double, as the value a robot reports would be. */
	private static Object asDouble(Object value) {
		return value instanceof Integer i ? Double.valueOf(i) : value;
	}

	private static Object literal(Expr e) {
		return e instanceof Expr.Lit l ? l.value() : e instanceof Expr.EnumLit l ? new org.triad.runtime.app.EnumValue(l.enumeration(), l.literal()) : null;
	}

}
