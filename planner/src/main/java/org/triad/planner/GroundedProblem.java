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
    private volatile boolean broken;

    /** A search query: the task, its initial state and goal, or the reason it is trivially unsolvable. */
    record Query(SearchTask task, int[] init, int[] goalPos, int[] goalNeg, String unsolvableReason, List<UnreachableGoal> unreachable) {
        Query {
            unreachable = List.copyOf(unreachable);
        }
    }

    GroundedProblem(Domain domain, Problem problem) {
        grounder = new Grounder(domain, problem);
        grounder.extend(problem.init());
    }

    /** Whether an extension was cut short (timeout, size refusal): the cache then grounds afresh. */
    boolean broken() {
        return broken;
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
            try {
                grounder.extend(problem.init());
            } catch (RuntimeException e) {
                // a timeout or a size refusal left the fixpoint half done: no later goal may use it
                broken = true;
                throw e;
            }
        }
        // Goal literals: a conjunction directly; otherwise the goal grounded with the static facts, and
        // if that leaves several disjuncts, one artificial operator per disjunct reaching a new goal fact.
        List<List<Normalizer.Lit>> dnf = liftedGoal(problem.goal());
        if (dnf == null || dnf.size() != 1) return disjunctiveQuery(problem);
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
                gp.add(id != null ? id : grounder.factId(p, args));
            } else if (id != null) {
                gn.add(id);
            }
        }
        refreshTask();
        int[] initIds = closed(task, initIds(problem));
        // Reachability from this initial state: the grounding may have been extended by earlier ones.
        List<UnreachableGoal> unreachable = new ArrayList<>();
        if (unsolvable == null) {
            boolean[] reached = ReachabilityExplainer.relaxedReach(task, initIds);
            ReachabilityExplainer explainer = null;
            for (int g : Grounder.sortedUnique(gp)) {
                if (reached[g]) continue;
                if (explainer == null) explainer = new ReachabilityExplainer(grounder, reached);
                int[] f = grounder.facts.get(g);
                unreachable.add(explainer.explain(f[0], java.util.Arrays.copyOfRange(f, 1, f.length)));
            }
            if (!unreachable.isEmpty()) {
                unsolvable = "goal " + (unreachable.size() > 1 ? "atoms are" : "atom is") + " unreachable even ignoring delete effects: "
                        + String.join("; ", unreachable.stream().map(UnreachableGoal::toString).toList());
            }
        }
        return new Query(task, initIds, Grounder.sortedUnique(gp), Grounder.sortedUnique(gn), unsolvable, unreachable);
    }

    private int[] initIds(Problem problem) {
        List<Integer> init = new ArrayList<>();
        for (Formula.Atom a : problem.init()) {
            int p = grounder.pred(a);
            if (grounder.fluent[p]) init.add(grounder.factId(p, ids(a)));
        }
        return Grounder.sortedUnique(init);
    }

    /** The goal's normal form over literals if it is small lifted (then static literals are checked one by one), else null. */
    private List<List<Normalizer.Lit>> liftedGoal(Formula goal) {
        try {
            return new Normalizer(grounder.universe, Grounder.LIFTED_QUANTIFIED_DISJUNCTS).dnf(goal);
        } catch (PlanningInputException e) {
            return null;
        }
    }

    /** Name of the artificial operators that reach a disjunctive goal (not a PDDL name, so it cannot clash). */
    static final String GOAL_ACTION = "(reach-goal)";

    private void refreshTask() {
        if (task == null || task.ops.length + task.ruleCount() != grounder.ops.size() || task.numFacts != grounder.facts.size()) {
            task = new SearchTask(grounder, grounder.ops, grounder.facts.size());
        }
    }

    /** The initial state with its derived facts. */
    private static int[] closed(SearchTask t, int[] init) {
        return t.axioms == null ? init : t.axioms.close(init);
    }

    private Query disjunctiveQuery(Problem problem) {
        List<GroundFormula.Conj> cases = new GroundFormula(grounder, true).dnf(problem.goal(), java.util.Map.of());
        refreshTask();
        int[] initIds = closed(task, initIds(problem));
        if (cases.isEmpty()) {
            return new Query(task, initIds, new int[0], new int[0], "the goal never holds (its static part is false)", List.of());
        }
        if (cases.size() == 1) {
            GroundFormula.Conj c = cases.get(0);
            return withReachability(task, initIds, c.pos(), c.neg(), "goal atom");
        }
        int goalFact = grounder.facts.size();
        List<GroundOp> ops = new ArrayList<>(grounder.ops);
        for (GroundFormula.Conj c : cases) {
            ops.add(new GroundOp(GOAL_ACTION, new String[0], c.pos(), c.neg(), new int[] {goalFact}, new int[0], 0, null, true));
        }
        SearchTask extended = new SearchTask(grounder, ops, goalFact + 1);
        boolean[] reached = ReachabilityExplainer.relaxedReach(extended, initIds);
        String unsolvable = reached[goalFact] ? null : "no disjunct of the goal is reachable even ignoring delete effects";
        return new Query(extended, initIds, new int[] {goalFact}, new int[0], unsolvable, List.of());
    }

    private Query withReachability(SearchTask t, int[] initIds, int[] goalPos, int[] goalNeg, String what) {
        boolean[] reached = ReachabilityExplainer.relaxedReach(t, initIds);
        List<UnreachableGoal> unreachable = new ArrayList<>();
        ReachabilityExplainer explainer = null;
        for (int g : goalPos) {
            if (reached[g]) continue;
            if (explainer == null) explainer = new ReachabilityExplainer(grounder, reached);
            int[] f = grounder.facts.get(g);
            unreachable.add(explainer.explain(f[0], java.util.Arrays.copyOfRange(f, 1, f.length)));
        }
        String unsolvable = unreachable.isEmpty() ? null
                : what + (unreachable.size() > 1 ? "s are" : " is") + " unreachable even ignoring delete effects: "
                        + String.join("; ", unreachable.stream().map(UnreachableGoal::toString).toList());
        return new Query(t, initIds, goalPos, goalNeg, unsolvable, unreachable);
    }

    private int[] ids(Formula.Atom a) {
        int[] t = new int[a.args().size()];
        for (int i = 0; i < t.length; i++) t[i] = grounder.universe.id(a.args().get(i));
        return t;
    }
}
