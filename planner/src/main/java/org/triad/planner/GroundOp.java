package org.triad.planner;

/**
 * A grounded action over fluent fact ids: positive and negative preconditions, add and delete
 * lists (a fact both added and deleted is only added: delete-then-add semantics).
 */
record GroundOp(String name, String[] args, int[] pre, int[] neg, int[] add, int[] del, double cost) {
    PddlStep toAction() {
        return new PddlStep(name, java.util.List.of(args));
    }
}
