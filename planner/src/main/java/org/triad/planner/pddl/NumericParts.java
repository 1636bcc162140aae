package org.triad.planner.pddl;

import java.util.ArrayList;
import java.util.List;

/** The numeric parts of formulas, effects and actions: which fluents they read or change. */
public final class NumericParts {
    private NumericParts() { }

    /** The fluents an expression reads, left to right. */
    public static List<NumericExpr.Fluent> fluents(NumericExpr e) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        collect(e, out);
        return out;
    }

    /** The fluents a comparison reads. */
    public static List<NumericExpr.Fluent> fluents(Formula.Compare c) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        collect(c.left(), out);
        collect(c.right(), out);
        return out;
    }

    /** The fluent a numeric effect changes, then those its value reads. */
    public static List<NumericExpr.Fluent> fluents(PddlEffect.NumericEffect n) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        out.add(n.target());
        collect(n.value(), out);
        return out;
    }

    /** Every fluent an action reads or changes (preconditions, conditions and numeric effects; not action costs). */
    public static List<NumericExpr.Fluent> fluents(Action a) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        formula(a.precondition(), out);
        effects(a.effects(), out);
        return out;
    }

    /** Whether a formula compares numbers anywhere. */
    public static boolean isNumeric(Formula f) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        return formula(f, out);
    }

    /** Whether an action compares numbers or has a numeric effect other than a constant action cost. */
    public static boolean isNumeric(Action a) {
        List<NumericExpr.Fluent> out = new ArrayList<>();
        return formula(a.precondition(), out) | effects(a.effects(), out);
    }

    /** Whether a domain has numeric conditions or effects beyond action costs. */
    public static boolean isNumeric(Domain d) {
        for (Action a : d.actions()) if (isNumeric(a)) return true;
        for (Axiom x : d.axioms()) if (isNumeric(x.body())) return true;
        return false;
    }

    private static boolean formula(Formula f, List<NumericExpr.Fluent> out) {
        if (f instanceof Formula.Compare c) {
            collect(c.left(), out);
            collect(c.right(), out);
            return true;
        }
        boolean found = false;
        if (f instanceof Formula.Not n) found = formula(n.body(), out);
        else if (f instanceof Formula.And a) for (Formula p : a.parts()) found |= formula(p, out);
        else if (f instanceof Formula.Or o) for (Formula p : o.parts()) found |= formula(p, out);
        else if (f instanceof Formula.Imply i) found = formula(i.condition(), out) | formula(i.consequence(), out);
        else if (f instanceof Formula.Forall q) found = formula(q.body(), out);
        else if (f instanceof Formula.Exists q) found = formula(q.body(), out);
        return found;
    }

    private static boolean effects(List<PddlEffect> effects, List<NumericExpr.Fluent> out) {
        boolean found = false;
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.NumericEffect n) {
                out.addAll(fluents(n));
                found = true;
            } else if (e instanceof PddlEffect.Forall q) found |= effects(q.body(), out);
            else if (e instanceof PddlEffect.When w) found |= formula(w.condition(), out) | effects(w.body(), out);
        }
        return found;
    }

    private static void collect(NumericExpr e, List<NumericExpr.Fluent> out) {
        if (e instanceof NumericExpr.Fluent f) out.add(f);
        else if (e instanceof NumericExpr.Arithmetic a) {
            collect(a.left(), out);
            collect(a.right(), out);
        } else if (e instanceof NumericExpr.Negation n) collect(n.operand(), out);
    }
}
