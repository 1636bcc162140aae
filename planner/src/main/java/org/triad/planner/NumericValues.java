package org.triad.planner;

import java.util.List;
import java.util.function.ToDoubleFunction;

import org.triad.planner.pddl.NumericExpr;
import org.triad.planner.pddl.PddlWriter;

/**
 * Evaluates PDDL 2.1 numeric expressions. Bad arithmetic is a {@link Fault} naming the expression,
 * never a silent NaN or infinity: a division by zero, a result too large for a double (overflow).
 */
public final class NumericValues {
    private NumericValues() { }

    /** A numeric expression that has no value: an undefined fluent, a division by zero, an overflow. */
    public static final class Fault extends RuntimeException {
        public Fault(String message) {
            super(message);
        }
    }

    /** The key of a ground fluent: its name and arguments separated by blanks, {@code battery r1}. */
    public static String key(String function, List<String> args) {
        return args.isEmpty() ? function : function + " " + String.join(" ", args);
    }

    /** {@code e} with its variables replaced by the objects {@code binding} gives them. */
    public static NumericExpr ground(NumericExpr e, java.util.Map<String, String> binding) {
        if (e instanceof NumericExpr.Fluent f) {
            return new NumericExpr.Fluent(f.name(), f.args().stream().map(t -> binding.getOrDefault(t, t)).toList());
        }
        if (e instanceof NumericExpr.Negation n) return new NumericExpr.Negation(ground(n.operand(), binding));
        if (e instanceof NumericExpr.Arithmetic a) return new NumericExpr.Arithmetic(a.op(), ground(a.left(), binding), ground(a.right(), binding));
        return e;
    }

    /** The value of {@code e}, reading ground fluents through {@code fluents} (which throws a Fault for one without a value). */
    public static double evaluate(NumericExpr e, ToDoubleFunction<NumericExpr.Fluent> fluents) {
        if (e instanceof NumericExpr.Number n) return n.value();
        if (e instanceof NumericExpr.Fluent f) return fluents.applyAsDouble(f);
        if (e instanceof NumericExpr.Negation n) return -evaluate(n.operand(), fluents);
        NumericExpr.Arithmetic a = (NumericExpr.Arithmetic) e;
        double l = evaluate(a.left(), fluents);
        double r = evaluate(a.right(), fluents);
        if (a.op() == '/' && r == 0) throw new Fault("division by zero in " + PddlWriter.expression(a));
        double v = switch (a.op()) {
            case '+' -> l + r;
            case '-' -> l - r;
            case '*' -> l * r;
            default -> l / r;
        };
        return checked(v, PddlWriter.expression(a));
    }

    /** {@code v} if it is a finite number, else a Fault saying {@code what} overflowed. */
    public static double checked(double v, String what) {
        if (Double.isNaN(v)) throw new Fault(what + " has no numeric value (NaN)");
        if (Double.isInfinite(v)) throw new Fault(what + " overflows (beyond " + Double.MAX_VALUE + ")");
        return v;
    }
}
