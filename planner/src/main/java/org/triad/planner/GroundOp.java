package org.triad.planner;

/**
 * A grounded action over fluent fact ids: positive and negative preconditions, add and delete
 * lists (a fact both added and deleted is only added: delete-then-add semantics), and conditional
 * effects ({@code when}), null when there are none (STRIPS operators stay as before).
 * {@code artificial} marks an operator the engine added itself (reaching a disjunctive goal): it
 * is dropped from the plan.
 */
record GroundOp(String name, String[] args, int[] pre, int[] neg, int[] add, int[] del, double cost, When[] when, boolean artificial) {
    GroundOp(String name, String[] args, int[] pre, int[] neg, int[] add, int[] del, double cost) {
        this(name, args, pre, neg, add, del, cost, null, false);
    }

    /**
     * A conditional effect: {@code add} and {@code del} apply when {@code pre} is true and {@code neg}
     * false in the state before the operator (all sorted fact ids).
     */
    record When(int[] pre, int[] neg, int[] add, int[] del) { }

    /** Name prefix of the rules of derived predicates, grounded like actions (not a PDDL name, so it cannot clash). */
    static final String AXIOM_PREFIX = "(derived) ";

    /** A rule of a derived predicate: its precondition is the rule's body, its one add the derived fact. */
    boolean isAxiom() {
        return name.startsWith(AXIOM_PREFIX);
    }

    PddlStep toAction() {
        return new PddlStep(name, java.util.List.of(args));
    }
}
