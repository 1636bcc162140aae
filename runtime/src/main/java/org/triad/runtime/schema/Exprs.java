package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/** Helpers over expression trees. */
public final class Exprs {
	private Exprs() {
	}

	/** The expression in the models' concrete syntax. */
	public static String show(Expr e) {
		if (e instanceof Expr.And a) {
			return paren(a.left(), e) + " && " + paren(a.right(), e);
		}
		if (e instanceof Expr.Or o) {
			return paren(o.left(), e) + " || " + paren(o.right(), e);
		}
		if (e instanceof Expr.Not n) {
			return "!" + paren(n.operand(), e);
		}
		if (e instanceof Expr.Compare c) {
			return show(c.left()) + " " + c.op().symbol + " " + show(c.right());
		}
		if (e instanceof Expr.Arith a) {
			return arithOperand(a.left(), a, false) + " " + a.op() + " " + arithOperand(a.right(), a, true);
		}
		if (e instanceof Expr.Call c) {
			return c.actor() + "." + c.property() + "(" + c.args().stream().map(Exprs::show).collect(Collectors.joining(", ")) + ")";
		}
		if (e instanceof Expr.Var v) {
			return v.name();
		}
		if (e instanceof Expr.Lit l) {
			return l.value() instanceof String s ? '"' + s + '"' : String.valueOf(l.value());
		}
		Expr.EnumLit l = (Expr.EnumLit) e;
		return l.enumeration() + "." + l.literal();
	}

	private static String arithOperand(Expr inner, Expr.Arith outer, boolean right) {
		boolean needs = inner instanceof Expr.Arith a && (rank(a.op()) < rank(outer.op()) || right && rank(a.op()) == rank(outer.op()));
		return needs ? "(" + show(inner) + ")" : show(inner);
	}

	private static int rank(char op) {
		return op == '+' || op == '-' ? 1 : 2;
	}

	private static String paren(Expr inner, Expr outer) {
		boolean needs = inner instanceof Expr.Or && !(outer instanceof Expr.Or)
				|| inner instanceof Expr.And && outer instanceof Expr.Not || inner instanceof Expr.Compare && outer instanceof Expr.Not;
		return needs ? "(" + show(inner) + ")" : show(inner);
	}

	/** The conjuncts of an expression ({@code a && b && c} gives a, b, c). */
	public static List<Expr> conjuncts(Expr e) {
		List<Expr> out = new ArrayList<>();
		add(e, out);
		return out;
	}

	private static void add(Expr e, List<Expr> out) {
		if (e instanceof Expr.And a) {
			add(a.left(), out);
			add(a.right(), out);
		} else if (!(e instanceof Expr.Lit l && Boolean.TRUE.equals(l.value()))) {
			out.add(e);
		}
	}

	/** The conjunction of expressions ({@code true} when empty). */
	public static Expr conjunction(List<Expr> parts) {
		Expr result = null;
		for (Expr p : parts) {
			result = result == null ? p : new Expr.And(result, p);
		}
		return result == null ? Expr.TRUE : result;
	}
}
