package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.triad.runtime.app.Atom;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.State;
import org.triad.runtime.app.Values;

/**
 * Evaluates model expressions in a state. Names are looked up in the binding first (parameters),
 * then among the state's objects (situations name objects directly). Closed world: a Boolean
 * property not stored is false; a non-Boolean property without a value equals nothing.
 */
public final class Evaluator {
	private final AppSchema schema;

	public Evaluator(AppSchema schema) {
		this.schema = schema;
	}

	public boolean holds(Expr e, State state, Map<String, Object> binding) {
		Object v = eval(e, state, binding);
		if (v instanceof Boolean b) {
			return b;
		}
		throw new ModelEvaluationException("not a condition: " + Exprs.show(e) + " is " + v);
	}

	public Object eval(Expr e, State state, Map<String, Object> binding) {
		if (e instanceof Expr.And a) {
			return holds(a.left(), state, binding) && holds(a.right(), state, binding);
		}
		if (e instanceof Expr.Or o) {
			return holds(o.left(), state, binding) || holds(o.right(), state, binding);
		}
		if (e instanceof Expr.Not n) {
			return !holds(n.operand(), state, binding);
		}
		if (e instanceof Expr.Compare c) {
			return compare(c, state, binding);
		}
		if (e instanceof Expr.Arith a) {
			return arithmetic(a, eval(a.left(), state, binding), eval(a.right(), state, binding));
		}
		if (e instanceof Expr.Call c) {
			Atom atom = atom(c, state, binding);
			boolean isBoolean = schema.property(c.actor(), c.property()).map(PropertySchema::isBoolean)
					.orElseThrow(() -> new ModelEvaluationException("unknown property " + c.actor() + "." + c.property()));
			if (schema.isAttribute(c.actor(), c.property())) {
				return attribute(atom, state);
			}
			return isBoolean ? state.holds(atom) : state.valueOf(atom).orElse(null);
		}
		if (e instanceof Expr.Var v) {
			if (binding.containsKey(v.name())) {
				return Values.canonical(binding.get(v.name()));
			}
			return state.object(v.name()).orElseThrow(() -> new ModelEvaluationException("unbound name '" + v.name() + "'"));
		}
		if (e instanceof Expr.Lit l) {
			return l.value();
		}
		Expr.EnumLit l = (Expr.EnumLit) e;
		return new EnumValue(l.enumeration(), l.literal());
	}

	/**
	 * {@code + - *} on two ints stay an int while the result fits; otherwise, and for {@code /}, a double.
	 * A division by zero, a result past the range of double, or an operand without a value is a model fault.
	 */
	static Object arithmetic(Expr.Arith a, Object l, Object r) {
		if (!(l instanceof Number x) || !(r instanceof Number y)) {
			throw new ModelEvaluationException("'" + a.op() + "' needs numbers: " + Exprs.show(a) + " reads "
					+ (l instanceof Number ? r : l) + (l == null || r == null ? " (a property without a value)" : ""));
		}
		if (a.op() == '/' && y.doubleValue() == 0) {
			throw new ModelEvaluationException("division by zero: " + Exprs.show(a));
		}
		if (a.op() != '/' && isIntegral(x) && isIntegral(y)) {
			long v = switch (a.op()) {
				case '+' -> x.longValue() + y.longValue();
				case '-' -> x.longValue() - y.longValue();
				default -> x.longValue() * y.longValue();
			};
			if (v >= Integer.MIN_VALUE && v <= Integer.MAX_VALUE) {
				return (int) v;
			}
		}
		double v = switch (a.op()) {
			case '+' -> x.doubleValue() + y.doubleValue();
			case '-' -> x.doubleValue() - y.doubleValue();
			case '*' -> x.doubleValue() * y.doubleValue();
			default -> x.doubleValue() / y.doubleValue();
		};
		if (!Double.isFinite(v)) {
			throw new ModelEvaluationException("overflow: " + Exprs.show(a) + " is " + v);
		}
		return v;
	}

	private static boolean isIntegral(Number n) {
		return n instanceof Integer || n instanceof Long || n instanceof Short || n instanceof Byte;
	}

	/** An attribute's value: as the state states it, else the object's own ({@code Item gauze { weight = 1; }}). */
	private static Object attribute(Atom atom, State state) {
		Optional<Object> stated = state.valueOf(atom);
		if (stated.isPresent()) {
			return stated.get();
		}
		Object value = atom.args().get(0) instanceof DomainObject o ? o.attribute(atom.property()) : null;
		return value == null ? null : Values.canonical(value);
	}

	/** The atom a call denotes in a state, its arguments evaluated. */
	public Atom atom(Expr.Call c, State state, Map<String, Object> binding) {
		List<Object> args = new ArrayList<>(c.args().size());
		for (Expr a : c.args()) {
			args.add(eval(a, state, binding));
		}
		return new Atom(c.actor(), c.property(), args);
	}

	private boolean compare(Expr.Compare c, State state, Map<String, Object> binding) {
		Object l = eval(c.left(), state, binding);
		Object r = eval(c.right(), state, binding);
		return switch (c.op()) {
			case EQ -> Values.same(l, r);
			case NE -> !Values.same(l, r);
			default -> {
				if (!(l instanceof Number a) || !(r instanceof Number b)) {
					throw new ModelEvaluationException("'" + c.op().symbol + "' needs numbers: " + Exprs.show(c));
				}
				double x = a.doubleValue();
				double y = b.doubleValue();
				yield switch (c.op()) {
					case LT -> x < y;
					case LE -> x <= y;
					case GT -> x > y;
					default -> x >= y;
				};
			}
		};
	}
}
