package org.triad.planner;

import java.util.List;

/** A sequential plan. */
public record PddlPlan(List<PddlStep> steps) {
    public PddlPlan {
        steps = List.copyOf(steps);
    }

    public int length() {
        return steps.size();
    }

    /** The plan as VAL reads it: one {@code (action args)} per line, then the unit cost. */
    public String toPddl() {
        return actions().append("; cost = ").append(steps.size()).append(" (unit cost)\n").toString();
    }

    /**
     * The plan as VAL reads it, then the value of the problem's {@code :metric} at its end (as VAL's
     * "Final value" reports it), for a problem that has one: its steps are not what it minimises.
     */
    public String toPddl(double metricValue) {
        return actions().append("; cost = ").append(plain(metricValue)).append(" (metric)\n").toString();
    }

    private StringBuilder actions() {
        StringBuilder sb = new StringBuilder();
        for (PddlStep a : steps) sb.append(a).append('\n');
        return sb;
    }

    private static String plain(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) return Long.toString((long) value);
        return java.math.BigDecimal.valueOf(value).stripTrailingZeros().toPlainString();
    }
}
