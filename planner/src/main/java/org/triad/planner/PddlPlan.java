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
        StringBuilder sb = new StringBuilder();
        for (PddlStep a : steps) sb.append(a).append('\n');
        return sb.append("; cost = ").append(steps.size()).append(" (unit cost)\n").toString();
    }
}
