package org.triad.planner.pddl;

import java.util.ArrayList;
import java.util.List;

/** Prints domains and problems as standard PDDL that other planners (FF, Fast Downward, PDDL4J) read. */
public final class PddlWriter {
    private PddlWriter() { }

    public static String write(Domain d) {
        StringBuilder sb = new StringBuilder();
        sb.append("(define (domain ").append(d.name()).append(")\n");
        if (!d.requirements().isEmpty()) sb.append("  (:requirements ").append(String.join(" ", d.requirements())).append(")\n");
        if (!d.types().isEmpty()) sb.append("  (:types ").append(typed(d.types())).append(")\n");
        if (!d.constants().isEmpty()) sb.append("  (:constants ").append(typed(d.constants())).append(")\n");
        sb.append("  (:predicates");
        for (PredicateDecl p : d.predicates()) sb.append("\n    ").append(decl(p));
        sb.append(")\n");
        if (!d.functions().isEmpty()) {
            sb.append("  (:functions");
            for (PredicateDecl p : d.functions()) sb.append(' ').append(decl(p));
            sb.append(")\n");
        }
        for (Action a : d.actions()) {
            sb.append("  (:action ").append(a.name()).append('\n');
            sb.append("    :parameters (").append(typed(a.parameters())).append(")\n");
            sb.append("    :precondition ").append(formula(a.precondition())).append('\n');
            sb.append("    :effect ").append(effects(a.effects())).append(")\n");
        }
        for (Axiom x : d.axioms()) {
            sb.append("  (:derived (").append(x.predicate());
            if (!x.parameters().isEmpty()) sb.append(' ').append(typed(x.parameters()));
            sb.append(")\n    ").append(formula(x.body())).append(")\n");
        }
        return sb.append(")\n").toString();
    }

    public static String write(Problem p) {
        StringBuilder sb = new StringBuilder();
        sb.append("(define (problem ").append(p.name()).append(")\n");
        sb.append("  (:domain ").append(p.domainName()).append(")\n");
        if (!p.objects().isEmpty()) sb.append("  (:objects ").append(typed(p.objects())).append(")\n");
        sb.append("  (:init");
        for (Formula.Atom a : p.init()) sb.append("\n    ").append(atom(a));
        for (Problem.NumericFact f : p.numericInit()) {
            sb.append("\n    (= (").append(f.function());
            for (String x : f.args()) sb.append(' ').append(x);
            sb.append(") ").append(number(f.value())).append(')');
        }
        sb.append(")\n");
        sb.append("  (:goal ").append(formula(p.goal())).append(")\n");
        if (p.metric() != null) sb.append("  (:metric ").append(p.metric()).append(")\n");
        return sb.append(")\n").toString();
    }

    public static String number(double v) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException("not a finite number, which PDDL cannot write: " + v);
        if (v == Math.rint(v) && Math.abs(v) < 1e15) return Long.toString((long) v);
        // plain decimals, never 1.0E20: Metric-FF, ENHSP and VAL read no exponents
        return new java.math.BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
    }

    /** Groups consecutive names of the same type: {@code a b - t c - u}. */
    static String typed(List<TypedName> names) {
        List<String> parts = new ArrayList<>();
        int i = 0;
        while (i < names.size()) {
            List<String> types = names.get(i).types();
            int j = i;
            StringBuilder group = new StringBuilder();
            while (j < names.size() && names.get(j).types().equals(types)) {
                if (group.length() > 0) group.append(' ');
                group.append(names.get(j).name());
                j++;
            }
            group.append(" - ").append(types.size() == 1 ? types.get(0) : "(either " + String.join(" ", types) + ")");
            parts.add(group.toString());
            i = j;
        }
        return String.join(" ", parts);
    }

    private static String decl(PredicateDecl p) {
        return p.parameters().isEmpty() ? "(" + p.name() + ")" : "(" + p.name() + " " + typed(p.parameters()) + ")";
    }

    public static String atom(Formula.Atom a) {
        if (a.args().isEmpty()) return "(" + a.predicate() + ")";
        return "(" + a.predicate() + " " + String.join(" ", a.args()) + ")";
    }

    public static String formula(Formula f) {
        if (f instanceof Formula.Atom a) return atom(a);
        if (f instanceof Formula.Equals e) return "(= " + e.left() + " " + e.right() + ")";
        if (f instanceof Formula.Not n) return "(not " + formula(n.body()) + ")";
        if (f instanceof Formula.And a) return nary("and", a.parts());
        if (f instanceof Formula.Or o) return nary("or", o.parts());
        if (f instanceof Formula.Imply i) return "(imply " + formula(i.condition()) + " " + formula(i.consequence()) + ")";
        if (f instanceof Formula.Forall q) return "(forall (" + typed(q.variables()) + ") " + formula(q.body()) + ")";
        if (f instanceof Formula.Compare c) return "(" + c.op() + " " + expression(c.left()) + " " + expression(c.right()) + ")";
        Formula.Exists q = (Formula.Exists) f;
        return "(exists (" + typed(q.variables()) + ") " + formula(q.body()) + ")";
    }

    private static String nary(String op, List<Formula> parts) {
        StringBuilder sb = new StringBuilder("(").append(op);
        for (Formula p : parts) sb.append(' ').append(formula(p));
        return sb.append(')').toString();
    }

    static String effects(List<PddlEffect> effects) {
        StringBuilder sb = new StringBuilder("(and");
        for (PddlEffect e : effects) sb.append(' ').append(effect(e));
        return sb.append(')').toString();
    }

    private static String effect(PddlEffect e) {
        if (e instanceof PddlEffect.Add a) return atom(a.atom());
        if (e instanceof PddlEffect.Delete d) return "(not " + atom(d.atom()) + ")";
        if (e instanceof PddlEffect.Forall q) return "(forall (" + typed(q.variables()) + ") " + effects(q.body()) + ")";
        if (e instanceof PddlEffect.When w) return "(when " + formula(w.condition()) + " " + effects(w.body()) + ")";
        if (e instanceof PddlEffect.NumericEffect n) return "(" + n.kind() + " " + expression(n.target()) + " " + expression(n.value()) + ")";
        PddlEffect.Increase i = (PddlEffect.Increase) e;
        return "(increase (" + i.function() + ") " + numeric(i.amount()) + ")";
    }

    /** A numeric expression of PDDL 2.1. */
    public static String expression(NumericExpr e) {
        if (e instanceof NumericExpr.Number n) return number(n.value());
        if (e instanceof NumericExpr.Fluent f) return f.args().isEmpty() ? "(" + f.name() + ")" : "(" + f.name() + " " + String.join(" ", f.args()) + ")";
        if (e instanceof NumericExpr.Negation n) return "(- " + expression(n.operand()) + ")";
        NumericExpr.Arithmetic a = (NumericExpr.Arithmetic) e;
        return "(" + a.op() + " " + expression(a.left()) + " " + expression(a.right()) + ")";
    }

    private static String numeric(NumericTerm t) {
        if (t instanceof NumericTerm.Constant c) return number(c.value());
        NumericTerm.Function f = (NumericTerm.Function) t;
        return f.args().isEmpty() ? "(" + f.name() + ")" : "(" + f.name() + " " + String.join(" ", f.args()) + ")";
    }
}
