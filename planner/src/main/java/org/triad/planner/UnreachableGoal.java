package org.triad.planner;

import java.util.List;
import java.util.stream.Collectors;
import org.triad.planner.pddl.Formula;

/**
 * Why a goal atom cannot be reached from the initial state, even ignoring delete effects: the
 * chain of facts it needs ({@code needs}, nearest first) down to the nearest missing facts. Atoms
 * in {@code needs} and {@code missing} are patterns: an argument {@value #ANY} stands for several
 * objects. {@link Kind#STATIC}: every action that would reach the last fact of the chain from
 * reachable facts needs a {@code missing} fact that no action can make (a static fact the state
 * lacks, e.g. a missing connection). {@link Kind#UNREACHED}: the {@code missing} facts are not in the
 * state, and every action making them needs the chain itself (e.g. an item that is nowhere).
 */
public record UnreachableGoal(Formula.Atom goal, List<Formula.Atom> needs, List<Formula.Atom> missing, Kind kind) {
    /** The argument of a pattern that stands for several objects. */
    public static final String ANY = "_";

    public enum Kind { STATIC, UNREACHED }

    public UnreachableGoal {
        needs = List.copyOf(needs);
        missing = List.copyOf(missing);
    }

    /** The explanation in PDDL terms, e.g. {@code (carries gauze) needs (item-at gauze _): none in the initial state ...}. */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder(goal.toString());
        for (Formula.Atom a : needs) sb.append(" needs ").append(a);
        String m = missing.stream().map(Formula.Atom::toString).collect(Collectors.joining(" or "));
        if (kind == Kind.STATIC) {
            sb.append(needs.isEmpty() ? ": no action reaches it without " : ", which no action reaches without ").append(m)
                    .append(", and the initial state lacks ").append(missing.size() > 1 ? "them" : "it");
        } else {
            sb.append(" needs ").append(m).append(": none in the initial state, and no action makes one from reachable facts");
        }
        return sb.toString();
    }
}
