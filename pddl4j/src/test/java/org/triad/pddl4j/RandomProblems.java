package org.triad.pddl4j;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlEffect;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.PredicateDecl;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Seeded random typed STRIPS tasks: a small type hierarchy, predicates of arity 0-2, actions with
 * positive and negative preconditions and (in)equalities, add and delete effects.
 */
final class RandomProblems {
    private static final List<String> TYPES = List.of("object", "a", "b", "c");

    private final Random rnd;

    RandomProblems(long seed) {
        rnd = new Random(seed);
    }

    /** Whether {@code sub} is {@code sup} or below it: b - a - object, c - object. */
    private static boolean isA(String sub, String sup) {
        if (sup.equals("object") || sub.equals(sup)) return true;
        return sub.equals("b") && sup.equals("a");
    }

    record Task(Domain domain, Problem problem) { }

    Task next() {
        while (true) {
            Task t = attempt();
            if (t != null) return t;
        }
    }

    private Task attempt() {
        int np = 2 + rnd.nextInt(4);
        List<PredicateDecl> preds = new ArrayList<>();
        for (int i = 0; i < np; i++) {
            int arity = rnd.nextInt(3);
            List<TypedName> params = new ArrayList<>();
            for (int k = 0; k < arity; k++) params.add(TypedName.of("?x" + k, TYPES.get(rnd.nextInt(TYPES.size()))));
            preds.add(new PredicateDecl("p" + i, params));
        }
        List<Action> actions = new ArrayList<>();
        int na = 1 + rnd.nextInt(4);
        for (int i = 0; i < na; i++) actions.add(action("act" + i, preds));
        Domain d = new Domain("rnd", List.of(":strips", ":typing", ":negative-preconditions", ":equality"),
                List.of(TypedName.of("a", "object"), TypedName.of("b", "a"), TypedName.of("c", "object")), List.of(), preds, List.of(), actions);
        List<TypedName> objects = new ArrayList<>();
        int no = 2 + rnd.nextInt(3);
        for (int i = 0; i < no; i++) objects.add(TypedName.of("o" + i, TYPES.get(1 + rnd.nextInt(3))));
        List<Formula.Atom> all = groundAtoms(preds, objects);
        List<Formula.Atom> init = new ArrayList<>();
        for (Formula.Atom a : all) if (rnd.nextInt(3) == 0) init.add(a);
        List<Formula> goal = new ArrayList<>();
        int ng = 1 + rnd.nextInt(3);
        for (int i = 0; i < ng && !all.isEmpty(); i++) {
            Formula.Atom a = all.get(rnd.nextInt(all.size()));
            goal.add(rnd.nextInt(5) == 0 ? new Formula.Not(a) : a);
        }
        if (goal.isEmpty()) return null;
        Problem p = new Problem("r", "rnd", objects, init, List.of(), new Formula.And(goal), null);
        return new Task(d, p);
    }

    private List<Formula.Atom> groundAtoms(List<PredicateDecl> preds, List<TypedName> objects) {
        List<Formula.Atom> out = new ArrayList<>();
        for (PredicateDecl p : preds) {
            List<List<String>> tuples = new ArrayList<>();
            tuples.add(List.of());
            for (TypedName param : p.parameters()) {
                List<List<String>> next = new ArrayList<>();
                for (List<String> t : tuples) {
                    for (TypedName o : objects) {
                        if (!isA(o.types().get(0), param.types().get(0))) continue;
                        List<String> n = new ArrayList<>(t);
                        n.add(o.name());
                        next.add(n);
                    }
                }
                tuples = next;
            }
            for (List<String> t : tuples) out.add(new Formula.Atom(p.name(), t));
        }
        return out;
    }

    private Action action(String name, List<PredicateDecl> preds) {
        int n = rnd.nextInt(3);
        List<TypedName> params = new ArrayList<>();
        for (int k = 0; k < n; k++) params.add(TypedName.of("?v" + k, TYPES.get(rnd.nextInt(TYPES.size()))));
        List<Formula> pre = new ArrayList<>();
        int npre = rnd.nextInt(4);
        for (int i = 0; i < npre; i++) {
            Formula.Atom a = atom(preds, params);
            if (a != null) pre.add(rnd.nextInt(4) == 0 ? new Formula.Not(a) : a);
        }
        if (params.size() == 2 && rnd.nextInt(3) == 0) {
            Formula eq = new Formula.Equals("?v0", "?v1");
            pre.add(rnd.nextBoolean() ? new Formula.Not(eq) : eq);
        }
        List<PddlEffect> eff = new ArrayList<>();
        int nadd = 1 + rnd.nextInt(2);
        for (int i = 0; i < nadd; i++) {
            Formula.Atom a = atom(preds, params);
            if (a != null) eff.add(new PddlEffect.Add(a));
        }
        int ndel = rnd.nextInt(3);
        for (int i = 0; i < ndel; i++) {
            Formula.Atom a = atom(preds, params);
            if (a != null) eff.add(new PddlEffect.Delete(a));
        }
        return new Action(name, params, new Formula.And(pre), eff);
    }

    /** An atom over the action's parameters respecting predicate types, or null if none fits. */
    private Formula.Atom atom(List<PredicateDecl> preds, List<TypedName> params) {
        for (int attempt = 0; attempt < 5; attempt++) {
            PredicateDecl p = preds.get(rnd.nextInt(preds.size()));
            List<String> args = new ArrayList<>();
            for (TypedName slot : p.parameters()) {
                List<String> fitting = new ArrayList<>();
                for (TypedName v : params) if (isA(v.types().get(0), slot.types().get(0))) fitting.add(v.name());
                if (fitting.isEmpty()) break;
                args.add(fitting.get(rnd.nextInt(fitting.size())));
            }
            if (args.size() == p.parameters().size()) return new Formula.Atom(p.name(), args);
        }
        return null;
    }
}
