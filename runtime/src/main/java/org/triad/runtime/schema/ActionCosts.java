package org.triad.runtime.schema;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.PredicateDecl;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.NumericTerm;
import org.triad.planner.pddl.TypedName;
import org.triad.runtime.app.GroundAction;

/**
 * What an action costs a goal's plan beyond its one step: the planning hook for congestion (a move into a
 * corridor others queue for costs its expected wait, so a robot may take the free side of the ring). With
 * costs, {@link GoalSolver} asks the planner for the plan of least total cost ({@code :metric minimize
 * (total-cost)}, every action {@code 1 + extra}) instead of the shortest. Asked once per ground action of the
 * goal's problem, at planning time: it answers from what it knows now (a reservation table's expected wait).
 */
@FunctionalInterface
public interface ActionCosts {
    /** Ground actions of one action at most this many: beyond, the action keeps cost 1 (no hook asked). */
    int MAX_GROUNDINGS = 20_000;

    /**
     * The extra cost of this action, in steps (0 for none; a wait of 30 s where one step takes 10 s is 3),
     * finite and not negative.
     */
    double extra(GroundAction action);

    /** The goal's problem with every action costing {@code 1 + extra} and the total cost minimised. */
    record Costed(Domain domain, Problem problem) {
    }

    /** Adds the costs to a translated goal (names from {@code task}, so the hook sees the application's objects). */
    static Costed apply(PddlTranslator.Task task, ActionCosts costs) {
        Domain d = task.domain();
        Problem p = task.problem();
        Map<String, String> parentOf = new HashMap<>();
        for (TypedName t : d.types()) {
            parentOf.put(t.name(), t.types().get(0));
        }
        Map<String, String> objects = new LinkedHashMap<>();
        d.constants().forEach(c -> objects.put(c.name(), c.types().get(0)));
        p.objects().forEach(o -> objects.put(o.name(), o.types().get(0)));
        List<Action> actions = new ArrayList<>();
        List<PredicateDecl> functions = new ArrayList<>(d.functions());
        functions.add(new PredicateDecl("total-cost", List.of()));
        List<Problem.NumericFact> facts = new ArrayList<>(p.numericInit());
        facts.add(new Problem.NumericFact("total-cost", List.of(), 0));
        for (Action a : d.actions()) {
            String fn = "cost-" + a.name();
            List<List<String>> groundings = groundings(a.parameters(), objects, parentOf);
            List<PddlEffect> effects = new ArrayList<>(a.effects());
            if (groundings == null) {
                effects.add(new PddlEffect.Increase("total-cost", new NumericTerm.Constant(1)));
            } else {
                functions.add(new PredicateDecl(fn, a.parameters()));
                effects.add(new PddlEffect.Increase("total-cost", new NumericTerm.Function(fn, a.parameters().stream().map(TypedName::name).toList())));
                for (List<String> args : groundings) {
                    double extra = costs.extra(task.action(a.name(), args));
                    if (!(extra >= 0) || Double.isInfinite(extra)) {
                        throw new IllegalArgumentException("the extra cost of " + a.name() + args + " is " + extra + "; a cost is a finite number, at least 0");
                    }
                    facts.add(new Problem.NumericFact(fn, args, 1 + extra));
                }
            }
            actions.add(new Action(a.name(), a.parameters(), a.precondition(), effects));
        }
        List<String> requirements = new ArrayList<>(d.requirements());
        if (!requirements.contains(":action-costs")) {
            requirements.add(":action-costs");
        }
        Domain costed = new Domain(d.name(), requirements, d.types(), d.constants(), d.predicates(), functions, actions, d.axioms());
        return new Costed(costed, new Problem(p.name(), p.domainName(), p.objects(), p.init(), facts, p.goal(), "minimize (total-cost)"));
    }

    /** Every tuple of objects of the parameters' types (subtypes included), or null when there are more than {@link #MAX_GROUNDINGS}. */
    private static List<List<String>> groundings(List<TypedName> params, Map<String, String> objects, Map<String, String> parentOf) {
        List<List<String>> all = new ArrayList<>();
        all.add(List.of());
        for (TypedName param : params) {
            List<String> fitting = objects.entrySet().stream().filter(o -> isA(o.getValue(), param.types(), parentOf)).map(Map.Entry::getKey).toList();
            if ((long) all.size() * fitting.size() > MAX_GROUNDINGS) {
                return null;
            }
            List<List<String>> next = new ArrayList<>();
            for (List<String> prefix : all) {
                for (String o : fitting) {
                    List<String> t = new ArrayList<>(prefix);
                    t.add(o);
                    next.add(t);
                }
            }
            all = next;
        }
        return all;
    }

    private static boolean isA(String type, List<String> wanted, Map<String, String> parentOf) {
        for (String t = type; t != null; t = parentOf.get(t)) {
            if (wanted.contains(t) || t.equals("object") && wanted.contains("object")) {
                return true;
            }
            if (t.equals(parentOf.get(t))) {
                return false;
            }
        }
        return false;
    }
}
