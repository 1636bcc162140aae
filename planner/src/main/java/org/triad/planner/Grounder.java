package org.triad.planner;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.triad.planner.pddl.Action;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Formula;
import org.triad.planner.pddl.NumericTerm;
import org.triad.planner.pddl.PredicateDecl;
import org.triad.planner.pddl.Problem;
import org.triad.planner.pddl.TypedName;

/**
 * Instantiates action schemas by a relaxed-reachability fixpoint (semi-naive: each newly reached
 * fact triggers joins of the schemas that mention it). Static predicates (in no effect) are only
 * looked up, never become state facts. The fixpoint can be continued with more initial facts, so
 * a grounding can be reused for later initial states: every action reachable from them is then
 * already instantiated.
 */
final class Grounder {
    final ObjectUniverse universe;
    final Map<String, Integer> predIds = new HashMap<>();
    final List<String> predNames = new ArrayList<>();
    final List<Integer> predArity = new ArrayList<>();
    final boolean[] fluent;

    private final List<Schema> schemas = new ArrayList<>();
    /** For each predicate: (schema, positive-literal index) pairs that a new fact can trigger. */
    private final List<List<int[]>> triggers = new ArrayList<>();

    private final Map<IntKey, Integer> factIds = new HashMap<>();
    final List<int[]> facts = new ArrayList<>(); // [pred, args...]
    private final BitSet queued = new BitSet();
    private final ArrayDeque<Integer> queue = new ArrayDeque<>();
    private final List<List<int[]>> tuples = new ArrayList<>();
    private final Map<Long, List<int[]>> index = new HashMap<>();
    private final Set<IntKey> staticFacts = new HashSet<>();
    private final Set<IntKey> seenBindings = new HashSet<>();
    private final Map<String, Double> numeric = new HashMap<>();

    final List<GroundOp> ops = new ArrayList<>();
    private final Normalizer normalizer;

    Grounder(Domain domain, Problem problem) {
        universe = new ObjectUniverse(domain, problem);
        normalizer = new Normalizer(universe);
        for (PredicateDecl p : domain.predicates()) {
            if (predIds.containsKey(p.name())) throw new PlanningInputException("predicate '" + p.name() + "' is declared twice");
            predIds.put(p.name(), predNames.size());
            predNames.add(p.name());
            predArity.add(p.parameters().size());
            tuples.add(new ArrayList<>());
            triggers.add(new ArrayList<>());
        }
        fluent = new boolean[predNames.size()];
        for (Action a : domain.actions()) {
            List<Normalizer.EffectLit> effs = new ArrayList<>();
            normalizer.effects(a.effects(), Map.of(), effs, new ArrayList<>());
            for (Normalizer.EffectLit e : effs) fluent[pred(e.atom())] = true;
        }
        for (Problem.NumericFact f : problem.numericInit()) numeric.put(numericKey(f.function(), f.args()), f.value());
        for (Action a : domain.actions()) {
            for (List<Normalizer.Lit> conj : normalizer.dnf(a.precondition())) compileSchema(a, conj);
        }
        for (Formula.Atom a : problem.init()) {
            int p = pred(a);
            if (!fluent[p]) {
                int[] t = objects(a);
                if (staticFacts.add(new IntKey(withPred(p, t)))) insertTuple(p, t);
            }
        }
        for (Schema s : schemas) {
            if (s.fluentLits == 0) join(s, s.emptyBinding(), new boolean[s.pos.length], s.pos.length);
        }
    }

    int pred(Formula.Atom a) {
        Integer p = predIds.get(a.predicate());
        if (p == null) throw new PlanningInputException("unknown predicate '" + a.predicate() + "'");
        if (predArity.get(p) != a.args().size()) {
            throw new PlanningInputException("predicate '" + a.predicate() + "' takes " + predArity.get(p) + " arguments, "
                    + a + " has " + a.args().size());
        }
        return p;
    }

    private int[] objects(Formula.Atom a) {
        int[] t = new int[a.args().size()];
        for (int i = 0; i < t.length; i++) t[i] = universe.id(a.args().get(i));
        return t;
    }

    private static int[] withPred(int p, int[] args) {
        int[] k = new int[args.length + 1];
        k[0] = p;
        System.arraycopy(args, 0, k, 1, args.length);
        return k;
    }

    boolean isStaticTrue(int pred, int[] args) {
        return staticFacts.contains(new IntKey(withPred(pred, args)));
    }

    /** The id of a ground fluent fact, created on first use. */
    int factId(int pred, int[] args) {
        IntKey k = new IntKey(withPred(pred, args));
        Integer id = factIds.get(k);
        if (id == null) {
            id = facts.size();
            factIds.put(k, id);
            facts.add(k.values);
        }
        return id;
    }

    Integer existingFactId(int pred, int[] args) {
        return factIds.get(new IntKey(withPred(pred, args)));
    }

    String factName(int fact) {
        int[] f = facts.get(fact);
        StringBuilder sb = new StringBuilder("(").append(predNames.get(f[0]));
        for (int i = 1; i < f.length; i++) sb.append(' ').append(universe.names.get(f[i]));
        return sb.append(')').toString();
    }

    boolean isReached(int fact) {
        return queued.get(fact);
    }

    /** Marks facts as initially true and continues the fixpoint; returns whether new actions appeared. */
    boolean extend(List<Formula.Atom> init) {
        int before = ops.size();
        for (Formula.Atom a : init) {
            int p = pred(a);
            if (!fluent[p]) continue;
            enqueue(factId(p, objects(a)));
        }
        run();
        return ops.size() != before;
    }

    private void enqueue(int fact) {
        if (!queued.get(fact)) {
            queued.set(fact);
            queue.add(fact);
        }
    }

    private void run() {
        while (!queue.isEmpty()) {
            int f = queue.poll();
            int[] k = facts.get(f);
            int p = k[0];
            int[] args = Arrays.copyOfRange(k, 1, k.length);
            insertTuple(p, args);
            for (int[] trig : triggers.get(p)) {
                Schema s = schemas.get(trig[0]);
                int[] b = s.emptyBinding();
                if (!unify(s, s.pos[trig[1]], args, b)) continue;
                boolean[] done = new boolean[s.pos.length];
                done[trig[1]] = true;
                join(s, b, done, s.pos.length - 1);
            }
        }
    }

    private void insertTuple(int p, int[] args) {
        tuples.get(p).add(args);
        for (int i = 0; i < args.length; i++) {
            index.computeIfAbsent(indexKey(p, i, args[i]), k -> new ArrayList<>()).add(args);
        }
    }

    private static long indexKey(int pred, int pos, int obj) {
        return ((long) pred << 40) | ((long) pos << 32) | (obj & 0xffffffffL);
    }

    // ---- schemas -------------------------------------------------------------------------------

    /** A literal template: predicate and terms (param index >= 0, constant object as -(id+1)). */
    record Tpl(int pred, int[] terms) { }

    private final class Schema {
        final int id;
        final String action;
        final List<TypedName> params;
        final Tpl[] pos;
        final boolean[] posFluent;
        final int fluentLits;
        final Tpl[] neg;
        final int[][] eq; // pairs of terms
        final boolean[] eqPositive;
        final Tpl[] add;
        final Tpl[] del;
        final List<NumericTerm> costs;
        final Map<String, Integer> paramIndex;

        Schema(int id, Action a, List<Normalizer.Lit> conj, List<Normalizer.EffectLit> effs, List<NumericTerm> costs) {
            this.id = id;
            this.action = a.name();
            this.params = a.parameters();
            this.costs = costs;
            paramIndex = new HashMap<>();
            for (int i = 0; i < params.size(); i++) paramIndex.put(params.get(i).name(), i);
            List<Tpl> p = new ArrayList<>();
            List<Tpl> n = new ArrayList<>();
            List<int[]> e = new ArrayList<>();
            List<Boolean> ep = new ArrayList<>();
            for (Normalizer.Lit l : conj) {
                if (l.atom() == null) {
                    e.add(new int[] {term(l.left()), term(l.right())});
                    ep.add(l.positive());
                } else {
                    Tpl t = tpl(l.atom());
                    (l.positive() ? p : n).add(t);
                }
            }
            pos = p.toArray(new Tpl[0]);
            posFluent = new boolean[pos.length];
            int fl = 0;
            for (int i = 0; i < pos.length; i++) {
                posFluent[i] = fluent[pos[i].pred];
                if (posFluent[i]) fl++;
            }
            fluentLits = fl;
            neg = n.toArray(new Tpl[0]);
            eq = e.toArray(new int[0][]);
            eqPositive = new boolean[ep.size()];
            for (int i = 0; i < eqPositive.length; i++) eqPositive[i] = ep.get(i);
            List<Tpl> ad = new ArrayList<>();
            List<Tpl> de = new ArrayList<>();
            for (Normalizer.EffectLit el : effs) (el.add() ? ad : de).add(tpl(el.atom()));
            add = ad.toArray(new Tpl[0]);
            del = de.toArray(new Tpl[0]);
        }

        int term(String t) {
            if (t.startsWith("?")) {
                Integer i = paramIndex.get(t);
                if (i == null) throw new PlanningInputException("variable '" + t + "' is not a parameter of action '" + action + "'");
                return i;
            }
            return -(universe.id(t) + 1);
        }

        Tpl tpl(Formula.Atom a) {
            int[] terms = new int[a.args().size()];
            for (int i = 0; i < terms.length; i++) terms[i] = term(a.args().get(i));
            return new Tpl(pred(a), terms);
        }

        int[] emptyBinding() {
            int[] b = new int[params.size()];
            Arrays.fill(b, -1);
            return b;
        }
    }

    private void compileSchema(Action a, List<Normalizer.Lit> conj) {
        List<Normalizer.EffectLit> effs = new ArrayList<>();
        List<NumericTerm> costs = new ArrayList<>();
        normalizer.effects(a.effects(), Map.of(), effs, costs);
        // A conjunction with a literal and its negation can never hold.
        Set<Formula.Atom> positive = new HashSet<>();
        for (Normalizer.Lit l : conj) if (l.atom() != null && l.positive()) positive.add(l.atom());
        for (Normalizer.Lit l : conj) if (l.atom() != null && !l.positive() && positive.contains(l.atom())) return;
        Schema s = new Schema(schemas.size(), a, conj, effs, costs);
        schemas.add(s);
        for (int i = 0; i < s.pos.length; i++) {
            if (s.posFluent[i]) triggers.get(s.pos[i].pred).add(new int[] {s.id, i});
        }
    }

    private boolean unify(Schema s, Tpl lit, int[] tuple, int[] b) {
        int[] terms = lit.terms;
        int boundHere = 0;
        int[] newly = new int[terms.length];
        for (int k = 0; k < terms.length; k++) {
            int t = terms[k];
            int o = tuple[k];
            boolean ok;
            if (t < 0) {
                ok = -(t + 1) == o;
            } else if (b[t] >= 0) {
                ok = b[t] == o;
            } else if (universe.isOf(o, s.params.get(t).types())) {
                b[t] = o;
                newly[boundHere++] = t;
                ok = true;
            } else {
                ok = false;
            }
            if (!ok) {
                for (int j = 0; j < boundHere; j++) b[newly[j]] = -1;
                return false;
            }
        }
        return true;
    }

    private void join(Schema s, int[] b, boolean[] done, int remaining) {
        if (remaining == 0) {
            enumerateFree(s, b, 0);
            return;
        }
        int best = -1;
        List<int[]> bestCands = null;
        for (int j = 0; j < s.pos.length; j++) {
            if (done[j]) continue;
            List<int[]> c = candidates(s.pos[j], b);
            if (bestCands == null || c.size() < bestCands.size()) {
                best = j;
                bestCands = c;
            }
        }
        if (bestCands.isEmpty()) return;
        done[best] = true;
        Tpl lit = s.pos[best];
        for (int[] tuple : bestCands) {
            int[] saved = b.clone();
            if (unify(s, lit, tuple, b)) join(s, b, done, remaining - 1);
            System.arraycopy(saved, 0, b, 0, b.length);
        }
        done[best] = false;
    }

    private List<int[]> candidates(Tpl lit, int[] b) {
        List<int[]> best = tuples.get(lit.pred);
        for (int k = 0; k < lit.terms.length; k++) {
            int t = lit.terms[k];
            int o = t < 0 ? -(t + 1) : b[t];
            if (o < 0) continue;
            List<int[]> l = index.get(indexKey(lit.pred, k, o));
            if (l == null) return List.of();
            if (l.size() < best.size()) best = l;
        }
        return best;
    }

    private void enumerateFree(Schema s, int[] b, int from) {
        for (int i = from; i < b.length; i++) {
            if (b[i] < 0) {
                for (int o : universe.ofTypes(s.params.get(i).types())) {
                    b[i] = o;
                    enumerateFree(s, b, i + 1);
                }
                b[i] = -1;
                return;
            }
        }
        instantiate(s, b);
    }

    private int value(int term, int[] b) {
        return term < 0 ? -(term + 1) : b[term];
    }

    private int[] args(Tpl t, int[] b) {
        int[] a = new int[t.terms.length];
        for (int i = 0; i < a.length; i++) a[i] = value(t.terms[i], b);
        return a;
    }

    private void instantiate(Schema s, int[] b) {
        for (int i = 0; i < s.eq.length; i++) {
            boolean same = value(s.eq[i][0], b) == value(s.eq[i][1], b);
            if (same != s.eqPositive[i]) return;
        }
        List<Integer> neg = new ArrayList<>();
        for (Tpl t : s.neg) {
            int[] a = args(t, b);
            if (!fluent[t.pred]) {
                if (isStaticTrue(t.pred, a)) return;
            } else {
                neg.add(factId(t.pred, a));
            }
        }
        int[] key = new int[b.length + 1];
        key[0] = s.id;
        System.arraycopy(b, 0, key, 1, b.length);
        if (!seenBindings.add(new IntKey(key))) return;
        List<Integer> pre = new ArrayList<>();
        for (int i = 0; i < s.pos.length; i++) {
            if (s.posFluent[i]) pre.add(factId(s.pos[i].pred, args(s.pos[i], b)));
        }
        int[] add = new int[s.add.length];
        for (int i = 0; i < add.length; i++) add[i] = factId(s.add[i].pred, args(s.add[i], b));
        List<Integer> del = new ArrayList<>();
        for (Tpl t : s.del) {
            int d = factId(t.pred, args(t, b));
            boolean added = false;
            for (int x : add) added |= x == d;
            if (!added) del.add(d);
        }
        double cost = 0;
        for (NumericTerm c : s.costs) cost += cost(c, s, b);
        String[] names = new String[b.length];
        for (int i = 0; i < b.length; i++) names[i] = universe.names.get(b[i]);
        ops.add(new GroundOp(s.action, names, sortedUnique(pre), sortedUnique(neg), sortedUnique(add), sortedUnique(del), cost));
        for (int f : add) enqueue(f);
    }

    private double cost(NumericTerm c, Schema s, int[] b) {
        if (c instanceof NumericTerm.Constant k) return k.value();
        NumericTerm.Function f = (NumericTerm.Function) c;
        List<String> args = new ArrayList<>();
        for (String t : f.args()) args.add(universe.names.get(value(s.term(t), b)));
        Double v = numeric.get(numericKey(f.name(), args));
        if (v == null) throw new PlanningInputException("no initial value for (" + f.name() + " " + String.join(" ", args) + ")");
        return v;
    }

    private static String numericKey(String f, List<String> args) {
        return f + " " + String.join(" ", args);
    }

    static int[] sortedUnique(List<Integer> xs) {
        int[] a = new int[xs.size()];
        for (int i = 0; i < a.length; i++) a[i] = xs.get(i);
        return sortedUnique(a);
    }

    static int[] sortedUnique(int[] xs) {
        if (xs.length == 0) return xs;
        int[] a = xs.clone();
        Arrays.sort(a);
        int n = 1;
        for (int i = 1; i < a.length; i++) if (a[i] != a[n - 1]) a[n++] = a[i];
        return n == a.length ? a : Arrays.copyOf(a, n);
    }
}
