package org.triad.planner.pddl;

import java.util.List;

/** A precondition or goal formula. Terms are object names or variables ({@code ?x}). */
public sealed interface Formula permits Formula.Atom, Formula.Equals, Formula.Not, Formula.And,
        Formula.Or, Formula.Imply, Formula.Forall, Formula.Exists, Formula.Compare {

    record Atom(String predicate, List<String> args) implements Formula {
        public Atom { args = List.copyOf(args); }
        public static Atom of(String predicate, String... args) { return new Atom(predicate, List.of(args)); }
        @Override public String toString() { return PddlWriter.atom(this); }
    }

    record Equals(String left, String right) implements Formula { }

    record Not(Formula body) implements Formula { }

    record And(List<Formula> parts) implements Formula {
        public And { parts = List.copyOf(parts); }
    }

    record Or(List<Formula> parts) implements Formula {
        public Or { parts = List.copyOf(parts); }
    }

    record Imply(Formula condition, Formula consequence) implements Formula { }

    record Forall(List<TypedName> variables, Formula body) implements Formula {
        public Forall { variables = List.copyOf(variables); }
    }

    record Exists(List<TypedName> variables, Formula body) implements Formula {
        public Exists { variables = List.copyOf(variables); }
    }

    /** A comparison of numeric expressions (PDDL 2.1): {@code op} is one of {@code < <= > >= =}. */
    record Compare(String op, NumericExpr left, NumericExpr right) implements Formula {
        public static final List<String> OPERATORS = List.of("<", "<=", ">", ">=", "=");

        public Compare {
            if (!OPERATORS.contains(op)) throw new IllegalArgumentException("not a comparison: " + op);
        }

        /** Whether {@code left op right} holds (false when either side is NaN, as in PDDL and Java). */
        public boolean holds(double l, double r) {
            return switch (op) {
                case "<" -> l < r;
                case "<=" -> l <= r;
                case ">" -> l > r;
                case ">=" -> l >= r;
                default -> l == r;
            };
        }
    }

    static boolean isVariable(String term) {
        return term.startsWith("?");
    }
}
