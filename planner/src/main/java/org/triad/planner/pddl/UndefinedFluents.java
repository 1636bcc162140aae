package org.triad.planner.pddl;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * A problem's numeric fluents that can never have a value, as located errors at the place that needs them.
 * PDDL 2.1 leaves a fluent undefined when {@code :init} gives it no value, and a ground action that reads
 * an undefined fluent simply does not apply; IPC problems rely on that (a {@code (distance a b)} only for
 * connected pairs), and even on a function that has no value for any arguments (pathwaysmetric's
 * {@code need-for-catalyzed-self-association}, umtranslog-2's {@code weight-cap-c}: an action the problems
 * never use), so what actions read is not checked (a "no plan" answer names such fluents). What is an error:
 * the goal or the metric reads a ground fluent that {@code :init} gives no value and that no action can
 * assign (the goal could never hold, the metric never be computed); the error is at the fluent's term.
 * {@code total-cost} and {@code total-time} start at 0 when the problem does not set them (as Metric-FF
 * and VAL take them), so they are never undefined.
 */
final class UndefinedFluents {
    private final Set<String> functions = new HashSet<>();
    private final Set<String> assigned = new HashSet<>();
    private final Set<String> valued = new HashSet<>();
    private final String source;

    private UndefinedFluents(Domain domain, Problem problem, String source) {
        this.source = source;
        domain.functions().forEach(f -> functions.add(f.name()));
        for (Action a : domain.actions()) assigns(a.effects());
        for (Problem.NumericFact f : problem.numericInit()) {
            valued.add(key(f.function(), f.args()));
        }
    }

    /** Throws a {@link PddlParseException} at the first place of {@code root} (the problem's s-expression) that needs a value it can never get. */
    static void check(Domain domain, Problem problem, SExpr root, String source) {
        new UndefinedFluents(domain, problem, source).check(root);
    }

    private void check(SExpr root) {
        for (SExpr sec : root.items.subList(2, root.items.size())) {
            String head = sec.head();
            if (":goal".equals(head)) fluents(sec.items.get(1), "the goal");
            if (":metric".equals(head)) fluents(sec.items.get(2), "the metric");
        }
    }

    /** The ground function terms under {@code e} (a goal's or metric's expression) that can never have a value. */
    private void fluents(SExpr e, String where) {
        if (!e.isList() || e.items.isEmpty()) return;
        String head = e.head();
        if (head != null && functions.contains(head)) {
            List<String> args = new ArrayList<>();
            for (SExpr a : e.items.subList(1, e.items.size())) {
                if (a.isList() || a.symbol.startsWith("?")) return; // quantified: the engine grounds it
                args.add(a.symbol);
            }
            if (!valued.contains(key(head, args)) && !assigned.contains(head) && !isAccumulator(head)) {
                throw new PddlParseException(source, e.line, e.column, where + " reads " + key(head, args)
                        + ", which :init gives no value and no action assigns, so " + (where.equals("the goal") ? "it could never hold" : "no plan has a value")
                        + "; give it one with (= " + key(head, args) + " NUMBER)");
            }
            return;
        }
        for (SExpr x : e.items) fluents(x, where);
    }

    private static boolean isAccumulator(String function) {
        return function.equals(PlanMetric.TOTAL_COST) || function.equals(PlanMetric.TOTAL_TIME);
    }

    private void assigns(List<PddlEffect> effects) {
        for (PddlEffect e : effects) {
            if (e instanceof PddlEffect.NumericEffect n && n.kind().equals("assign")) assigned.add(n.target().name());
            else if (e instanceof PddlEffect.Forall q) assigns(q.body());
            else if (e instanceof PddlEffect.When w) assigns(w.body());
        }
    }

    private static String key(String function, List<String> args) {
        return "(" + function + (args.isEmpty() ? "" : " " + String.join(" ", args)) + ")";
    }
}
