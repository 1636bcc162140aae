package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.triad.planner.pddl.Formula;

/**
 * Explains unreachable goal atoms from a relaxed reachability analysis (delete effects and negative
 * preconditions ignored). Searches backwards from the goal atom through the action schemas, lifted,
 * so it also sees actions the grounding never instantiated: an achiever whose static preconditions
 * hold but whose fluent ones are unreachable leads to those facts; one whose fluent preconditions are
 * reachable but whose static ones are false names those static facts as missing. Only the achievers
 * lacking the fewest facts are followed. The nearest missing facts are then the static facts of the
 * fact on the way that lacks the fewest of them (nearest the goal on ties), or, if no static fact is
 * missing, the deepest unreached facts: those that nothing reachable can make (an item that is nowhere).
 * Bounded in facts visited and bindings tried, so it answers quickly on any problem.
 */
final class ReachabilityExplainer {
    static final int MAX_FACTS = 2000;
    static final long MAX_BINDINGS = 500_000;

    private final Grounder g;
    private final boolean[] reached;
    private long bindings;

    /** {@code reached}: fluent fact ids reachable from the initial state (relaxed). */
    ReachabilityExplainer(Grounder grounder, boolean[] reached) {
        this.g = grounder;
        this.reached = reached;
    }

    /** Fluent facts reachable from {@code init} ignoring deletes, over the grounded actions. */
    static boolean[] relaxedReach(SearchTask task, int[] init) {
        RelaxedOps t = task.relaxed;
        boolean[] reach = new boolean[t.size];
        int[] unsat = new int[t.count];
        for (int o = 0; o < unsat.length; o++) unsat[o] = t.pre[o].length;
        int[] fifo = new int[t.size];
        init = t.initial(init);
        int tail = 0;
        for (int f : init) if (!reach[f]) { reach[f] = true; fifo[tail++] = f; }
        for (int o : t.noPre) for (int a : t.add[o]) if (!reach[a]) { reach[a] = true; fifo[tail++] = a; }
        for (int head = 0; head < tail; head++) {
            for (int o : t.preOf[fifo[head]]) {
                if (--unsat[o] == 0) for (int a : t.add[o]) if (!reach[a]) { reach[a] = true; fifo[tail++] = a; }
            }
        }
        return reach;
    }

    private boolean holds(int pred, int[] args) {
        if (!g.fluent[pred]) return g.isStaticTrue(pred, args);
        Integer id = g.existingFactId(pred, args);
        return id != null && id < reached.length && reached[id];
    }

    private record Node(int pred, int[] args, int parent, int depth) { }

    UnreachableGoal explain(int pred, int[] args) {
        List<Node> nodes = new ArrayList<>();
        Map<IntKey, Integer> seen = new HashMap<>();
        nodes.add(new Node(pred, args, -1, 0));
        seen.put(key(pred, args), 0);
        Map<Integer, List<int[]>> missingStatic = new LinkedHashMap<>();
        for (int i = 0; i < nodes.size() && bindings < MAX_BINDINGS; i++) {
            Node n = nodes.get(i);
            closest.clear();
            closestMissing = Integer.MAX_VALUE;
            for (Grounder.Schema s : g.schemas()) {
                // conditional adds count as achievers too (their conditions are not followed: a relaxation)
                for (Grounder.Tpl[] adds : new Grounder.Tpl[][] {s.add, s.condAdd}) {
                    for (Grounder.Tpl add : adds) {
                        if (add.pred() != n.pred) continue;
                        int[] b = s.emptyBinding();
                        if (!bind(s, add, n.args, b)) continue;
                        enumerate(s, b, 0);
                    }
                }
            }
            // follow only the achievers that lack the fewest facts: the others are further away
            for (List<int[]>[] c : closest) {
                List<int[]> statics = c[0];
                List<int[]> fluents = c[1];
                if (statics.isEmpty()) {
                    for (int[] f : fluents) {
                        IntKey k = new IntKey(f);
                        if (seen.containsKey(k) || nodes.size() >= MAX_FACTS) continue;
                        seen.put(k, nodes.size());
                        nodes.add(new Node(f[0], java.util.Arrays.copyOfRange(f, 1, f.length), i, n.depth + 1));
                    }
                } else if (fluents.isEmpty()) {
                    missingStatic.computeIfAbsent(i, k -> new ArrayList<>()).addAll(statics);
                }
            }
        }
        // the fact that lacks the fewest static facts, nearest the goal on ties (the order of discovery)
        int end = -1;
        for (Map.Entry<Integer, List<int[]>> e : missingStatic.entrySet()) {
            if (end < 0 || distinct(e.getValue()) < distinct(missingStatic.get(end))) end = e.getKey();
        }
        UnreachableGoal.Kind kind = UnreachableGoal.Kind.STATIC;
        List<Formula.Atom> missing;
        if (end >= 0) {
            missing = patterns(missingStatic.get(end));
        } else {
            kind = UnreachableGoal.Kind.UNREACHED;
            end = 0;
            for (int i = 0; i < nodes.size(); i++) if (nodes.get(i).depth > nodes.get(end).depth) end = i;
            List<int[]> layer = new ArrayList<>();
            Node e = nodes.get(end);
            for (Node n : nodes) if (n.depth == e.depth && n.pred == e.pred) layer.add(withPred(n.pred, n.args));
            missing = patterns(layer);
            end = e.parent; // the missing facts end the chain
        }
        List<Formula.Atom> needs = new ArrayList<>();
        // the chain between the goal and the end node (one fact per step: the first found)
        for (int i = end; i > 0; i = nodes.get(i).parent) needs.add(0, atom(nodes.get(i).pred, nodes.get(i).args));
        return new UnreachableGoal(atom(pred, args), needs, missing, kind);
    }

    private static int distinct(List<int[]> facts) {
        java.util.Set<IntKey> d = new java.util.HashSet<>();
        for (int[] f : facts) d.add(new IntKey(f));
        return d.size();
    }

    /** Binds the schema parameters so that {@code tpl} equals the fact; false if constants or types disagree. */
    private boolean bind(Grounder.Schema s, Grounder.Tpl tpl, int[] args, int[] b) {
        for (int k = 0; k < args.length; k++) {
            int t = tpl.terms()[k];
            if (t < 0) {
                if (-(t + 1) != args[k]) return false;
            } else if (b[t] >= 0) {
                if (b[t] != args[k]) return false;
            } else {
                if (!g.universe.isOf(args[k], s.params.get(t).types())) return false;
                b[t] = args[k];
            }
        }
        return true;
    }

    /** The achiever instances of the fact being explained that lack the fewest facts: [static, fluent] lists. */
    private final List<List<int[]>[]> closest = new ArrayList<>();
    private int closestMissing;

    private void enumerate(Grounder.Schema s, int[] b, int from) {
        for (int i = from; i < b.length; i++) {
            if (b[i] < 0) {
                for (int o : g.universe.ofTypes(s.params.get(i).types())) {
                    if (bindings >= MAX_BINDINGS) break;
                    b[i] = o;
                    enumerate(s, b, i + 1);
                }
                b[i] = -1;
                return;
            }
        }
        bindings++;
        for (int i = 0; i < s.eq.length; i++) {
            if ((Grounder.value(s.eq[i][0], b) == Grounder.value(s.eq[i][1], b)) != s.eqPositive[i]) return;
        }
        for (Grounder.Tpl t : s.neg) {
            if (!g.fluent[t.pred()] && g.isStaticTrue(t.pred(), Grounder.args(t, b))) return;
        }
        List<int[]> statics = new ArrayList<>();
        List<int[]> fluents = new ArrayList<>();
        for (Grounder.Tpl t : s.pos) {
            int[] a = Grounder.args(t, b);
            if (holds(t.pred(), a)) continue;
            (g.fluent[t.pred()] ? fluents : statics).add(withPred(t.pred(), a));
        }
        int lacking = statics.size() + fluents.size();
        if (lacking == 0 || lacking > closestMissing) return;
        if (lacking < closestMissing) {
            closest.clear();
            closestMissing = lacking;
        }
        @SuppressWarnings("unchecked")
        List<int[]>[] c = new List[] {statics, fluents};
        closest.add(c);
    }

    /** Groups facts by predicate; an argument that differs within a group becomes {@value UnreachableGoal#ANY}. */
    private List<Formula.Atom> patterns(List<int[]> facts) {
        Map<Integer, String[]> byPred = new LinkedHashMap<>();
        for (int[] f : facts) {
            String[] p = byPred.get(f[0]);
            if (p == null) {
                p = new String[f.length - 1];
                for (int i = 1; i < f.length; i++) p[i - 1] = g.universe.names.get(f[i]);
                byPred.put(f[0], p);
            } else {
                for (int i = 1; i < f.length; i++) if (!p[i - 1].equals(g.universe.names.get(f[i]))) p[i - 1] = UnreachableGoal.ANY;
            }
        }
        List<Formula.Atom> out = new ArrayList<>();
        byPred.forEach((pred, args) -> out.add(new Formula.Atom(g.predNames.get(pred), List.of(args))));
        return out;
    }

    private Formula.Atom atom(int pred, int[] args) {
        List<String> names = new ArrayList<>();
        for (int a : args) names.add(g.universe.names.get(a));
        return new Formula.Atom(g.predNames.get(pred), names);
    }

    private static int[] withPred(int pred, int[] args) {
        int[] k = new int[args.length + 1];
        k[0] = pred;
        System.arraycopy(args, 0, k, 1, args.length);
        return k;
    }

    private static IntKey key(int pred, int[] args) {
        return new IntKey(withPred(pred, args));
    }
}
