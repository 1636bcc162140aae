package org.triad.planner;

import java.util.List;
import java.util.stream.Collectors;
import org.triad.planner.pddl.Formula;

/**
 * Why a goal atom cannot be reached from the initial state, even ignoring delete effects: the
 * chain of facts it needs ({@code needs}, nearest first) down to the nearest missing facts. Atoms
 * in {@code needs} and {@code missing} are patterns: an argument {@value #ANY} stands for several
 * objects (in {@code missing} of kind STATIC: any object that can be reached). {@link Kind#STATIC}:
 * every action that would reach the last fact of the chain from reachable facts needs a
 * {@code missing} fact that no action can make (a static fact the state lacks, e.g. a missing connection). {@link Kind#UNREACHED}: the {@code missing} facts are not in the
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

    /** {@code " (for any reachable _)"} if a pattern has a {@value #ANY}: it ranges over what the state can reach. */
    public static String anyNote(List<Formula.Atom> patterns) {
        return patterns.stream().anyMatch(a -> a.args().contains(ANY)) ? " (for any reachable " + ANY + ")" : "";
    }

    /** The explanation in PDDL terms, e.g. {@code (carries gauze) needs (item-at gauze _): none in the initial state ...}. */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder(goal.toString());
        for (Formula.Atom a : needs) sb.append(" needs ").append(a);
        String m = missing.stream().map(Formula.Atom::toString).collect(Collectors.joining(" or "));
        if (kind == Kind.STATIC) {
            sb.append(": the actions that could reach it need ").append(m).append(anyNote(missing)).append(", which the initial state lacks");
        } else {
            sb.append(" needs ").append(m).append(": none in the initial state, and no action makes one from reachable facts");
        }
        return sb.toString();
    }
}
