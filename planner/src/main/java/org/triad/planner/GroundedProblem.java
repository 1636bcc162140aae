package org.triad.planner;

import java.util.ArrayList;
import java.util.List;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.Problem;

/**
 * The grounded static structure of a task (objects, static facts, reachable ground actions), kept
 * across goals. {@link #query} adapts it to a problem with the same objects and static facts but
 * any initial state and goal; only initial facts outside everything reached so far make the
 * grounding continue (counted by {@link #extensions()}).
 */
public final class GroundedProblem {
    private final Grounder grounder;
    private SearchTask task;
    private int extensions;

    /** A search query: the task, its initial state and goal, or the reason it is trivially unsolvable. */
    record Query(SearchTask task, int[] init, int[] goalPos, int[] goalNeg, String unsolvableReason) { }

    GroundedProblem(Domain domain, Problem problem) {
        grounder = new Grounder(domain, problem);
        grounder.extend(problem.init());
    }

    /** Ground actions instantiated so far. */
    public int actionCount() {
        return grounder.ops.size();
    }

    public int factCount() {
        return grounder.facts.size();
    }

    /** How many times a later query had to continue the grounding fixpoint. */
    public int extensions() {
        return extensions;
    }

    synchronized Query query(Problem problem) {
        boolean needsExtension = false;
        for (Formula.Atom a : problem.init()) {
            int p = grounder.pred(a);
            if (!grounder.fluent[p]) continue;
            Integer id = grounder.existingFactId(p, ids(a));
            if (id == null || !grounder.isReached(id)) {
                needsExtension = true;
                break;
            }
        }
        if (needsExtension) {
            extensions++;
            grounder.extend(problem.init());
        }
        // Goal literals: one conjunction directly; a disjunctive goal would need goal actions.
        List<List<Normalizer.Lit>> dnf = new Normalizer(grounder.universe).dnf(problem.goal());
        if (dnf.size() != 1) {
            throw new PlanningInputException("disjunctive goals are not supported by the Triad engine; rewrite the goal as a conjunction");
        }
        List<Integer> gp = new ArrayList<>();
        List<Integer> gn = new ArrayList<>();
        String unsolvable = null;
        for (Normalizer.Lit l : dnf.get(0)) {
            if (l.atom() == null) {
                boolean same = grounder.universe.id(l.left()) == grounder.universe.id(l.right());
                if (same != l.positive()) unsolvable = "goal " + (l.positive() ? "" : "not ") + "(= " + l.left() + " " + l.right() + ") is false";
                continue;
            }
            int p = grounder.pred(l.atom());
            int[] args = ids(l.atom());
            if (!grounder.fluent[p]) {
                if (grounder.isStaticTrue(p, args) != l.positive()) unsolvable = "static goal literal " + l.atom() + " never holds";
                continue;
            }
            Integer id = grounder.existingFactId(p, args);
            if (l.positive()) {
                if (id == null || !grounder.isReached(id)) {
                    unsolvable = "goal " + l.atom() + " is unreachable even ignoring delete effects";
                    id = grounder.factId(p, args);
                }
                gp.add(id);
            } else if (id != null) {
                gn.add(id);
            }
        }
        List<Integer> init = new ArrayList<>();
        for (Formula.Atom a : problem.init()) {
            int p = grounder.pred(a);
            if (grounder.fluent[p]) init.add(grounder.factId(p, ids(a)));
        }
        if (task == null || task.ops.length != grounder.ops.size() || task.numFacts != grounder.facts.size()) {
            task = new SearchTask(grounder, grounder.ops, grounder.facts.size());
        }
        return new Query(task, Grounder.sortedUnique(init), Grounder.sortedUnique(gp), Grounder.sortedUnique(gn), unsolvable);
    }

    private int[] ids(Formula.Atom a) {
        int[] t = new int[a.args().size()];
        for (int i = 0; i < t.length; i++) t[i] = grounder.universe.id(a.args().get(i));
        return t;
    }
}
