package org.triad.planner.pddl;

import java.util.List;

/**
 * A problem's {@code (:metric minimize|maximize EXPRESSION)}: what the engine optimises. The expression
 * is PDDL 2.1's: numbers, fluents and arithmetic, where {@code (total-cost)} is the sum of the plan's
 * {@code (increase (total-cost) X)} effects and {@code (total-time)} its number of steps (plans are
 * sequential). A problem without a {@code :metric} has none: the engine then prefers shorter plans.
 */
public record PlanMetric(boolean minimize, NumericExpr expression) {
    /** The fluent that sums action costs. */
    public static final String TOTAL_COST = "total-cost";
    /** The fluent that counts a sequential plan's steps. */
    public static final String TOTAL_TIME = "total-time";

    /** The metric of {@code problem}, or null when it has none (the parser has checked its form). */
    public static PlanMetric of(Problem problem) {
        if (problem.metric() == null || problem.metric().isBlank()) return null;
        return PddlParser.parseMetric(problem.metric(), problem.name() + " :metric");
    }

    /** {@code minimize (total-cost)}: the classical planners' action costs. */
    public boolean isTotalCost() {
        return minimize && expression instanceof NumericExpr.Fluent f && f.name().equals(TOTAL_COST) && f.args().isEmpty();
    }

    /** The fluents the metric reads (total-cost and total-time included). */
    public List<NumericExpr.Fluent> fluents() {
        return NumericParts.fluents(expression);
    }

    /** As the problem file writes it: {@code minimize (total-cost)}. */
    @Override
    public String toString() {
        return (minimize ? "minimize " : "maximize ") + PddlWriter.expression(expression);
    }
}
