package org.triad.planner.pddl;

import java.util.List;

/** A number or a function application (only what action costs need). */
public sealed interface NumericTerm permits NumericTerm.Constant, NumericTerm.Function {
    record Constant(double value) implements NumericTerm { }

    record Function(String name, List<String> args) implements NumericTerm {
        public Function { args = List.copyOf(args); }
    }
}
