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
import org.triad.planner.pddl.Axiom;
import org.triad.planner.pddl.PddlEffect;
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
    /** Derived predicates (defined by rules, never by effects) and their strata. */
    final boolean[] derived;
    final int[] stratum;

    private final List<Schema> schemas = new ArrayList<>();

    List<Schema> schemas() {
        return schemas;
    }
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
    /** The timeout of the thread grounding now (set again by every {@link #extend}). */
    private GroundingLimits.Clock clock = GroundingLimits.clock();
    private final Normalizer normalizer;
    private final GroundFormula groundFormula;
    /** Lifted normal forms of quantified preconditions beyond this size are grounded per operator instead. */
    static final int LIFTED_QUANTIFIED_DISJUNCTS = 64;

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
        derived = new boolean[predNames.size()];
        stratum = new int[predNames.size()];
        Map<String, Integer> strata = DerivedStrata.of(domain);
        for (Map.Entry<String, Integer> e : strata.entrySet()) {
            Integer p = predIds.get(e.getKey());
            if (p == null) throw new PlanningInputException("derived predicate '" + e.getKey() + "' is not declared");
            derived[p] = true;
            fluent[p] = true;
            stratum[p] = e.getValue();
        }
        for (Action a : domain.actions()) {
            List<Normalizer.EffectLit> effs = new ArrayList<>();
            List<Normalizer.CondEffect> conds = new ArrayList<>();
            normalizer.effects(a.effects(), Map.of(), effs, new ArrayList<>(), conds);
            for (Normalizer.CondEffect c : conds) effs.addAll(c.effects());
            for (Normalizer.EffectLit e : effs) fluent[pred(e.atom())] = true;
        }
        for (Problem.NumericFact f : problem.numericInit()) numeric.put(numericKey(f.function(), f.args()), f.value());
        groundFormula = new GroundFormula(this, false);
        List<Action> schemasToGround = new ArrayList<>(domain.actions());
        for (Axiom x : domain.axioms()) {
            // a rule grounds like an action whose only effect is its derived fact
            List<String> vars = x.parameters().stream().map(TypedName::name).toList();
            schemasToGround.add(new Action(GroundOp.AXIOM_PREFIX + x.predicate(), x.parameters(), x.body(),
                    List.of(new PddlEffect.Add(new Formula.Atom(x.predicate(), vars)))));
        }
        for (Action a : schemasToGround) {
            List<List<Normalizer.Lit>> dnf = liftedDnf(a.precondition());
            if (dnf != null) {
                for (List<Normalizer.Lit> conj : dnf) compileSchema(a, conj, null);
            } else {
                List<Normalizer.Lit> lits = new ArrayList<>();
                List<Formula> rest = new ArrayList<>();
                splitConjunction(a.precondition(), lits, rest);
                compileSchema(a, lits, new Formula.And(rest));
            }
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

    /**
     * The precondition's disjunctive normal form over the action parameters, or null when it is too
     * large lifted (a quantifier over many objects around a disjunction): then the operator's
     * instances evaluate it once its parameters and the static facts are known ({@link GroundFormula}).
     */
    private List<List<Normalizer.Lit>> liftedDnf(Formula pre) {
        boolean quantified = hasQuantifier(pre);
        try {
            return new Normalizer(universe, quantified ? LIFTED_QUANTIFIED_DISJUNCTS : Normalizer.MAX_DISJUNCTS).dnf(pre);
        } catch (PlanningInputException e) {
            return null;
        }
    }

    private static boolean hasQuantifier(Formula f) {
        if (f instanceof Formula.Forall || f instanceof Formula.Exists) return true;
        if (f instanceof Formula.Not n) return hasQuantifier(n.body());
        if (f instanceof Formula.And a) return a.parts().stream().anyMatch(Grounder::hasQuantifier);
        if (f instanceof Formula.Or o) return o.parts().stream().anyMatch(Grounder::hasQuantifier);
        if (f instanceof Formula.Imply i) return hasQuantifier(i.condition()) || hasQuantifier(i.consequence());
        return false;
    }

    /** The literals of a top-level conjunction (they drive the join) and the other conjuncts. */
    private static void splitConjunction(Formula f, List<Normalizer.Lit> lits, List<Formula> rest) {
        if (f instanceof Formula.And a) {
            for (Formula p : a.parts()) splitConjunction(p, lits, rest);
        } else if (f instanceof Formula.Atom a) {
            lits.add(new Normalizer.Lit(a, null, null, true));
        } else if (f instanceof Formula.Equals e) {
            lits.add(new Normalizer.Lit(null, e.left(), e.right(), true));
        } else if (f instanceof Formula.Not n && n.body() instanceof Formula.Atom a) {
            lits.add(new Normalizer.Lit(a, null, null, false));
        } else if (f instanceof Formula.Not n && n.body() instanceof Formula.Equals e) {
            lits.add(new Normalizer.Lit(null, e.left(), e.right(), false));
        } else {
            rest.add(f);
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

    /** Whether a fact id (of this grounding) is a derived fact. */
    boolean isDerivedFact(int fact) {
        return fact < facts.size() && derived[facts.get(fact)[0]];
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
        clock = GroundingLimits.clock();
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

    /** A conditional effect of a schema: its condition over the parameters and its literal effects. */
    record CondTpl(Formula condition, Tpl[] add, Tpl[] del) { }

    /** A conjunctive case of an action schema, over parameter indexes and constants. */
    final class Schema {
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
        /** The part of the precondition evaluated per instance ({@link GroundFormula}), or null. */
        final Formula residual;
        final List<CondTpl> conds;
        /** The add templates of all conditional effects (achievers for the reachability explanation). */
        final Tpl[] condAdd;

        Schema(int id, Action a, List<Normalizer.Lit> conj, List<Normalizer.EffectLit> effs, List<NumericTerm> costs,
               Formula residual, List<Normalizer.CondEffect> condEffects) {
            this.id = id;
            this.residual = residual;
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
            conds = new ArrayList<>();
            List<Tpl> ca = new ArrayList<>();
            for (Normalizer.CondEffect c : condEffects) {
                List<Tpl> cad = new ArrayList<>();
                List<Tpl> cde = new ArrayList<>();
                for (Normalizer.EffectLit el : c.effects()) (el.add() ? cad : cde).add(tpl(el.atom()));
                conds.add(new CondTpl(c.condition(), cad.toArray(new Tpl[0]), cde.toArray(new Tpl[0])));
                ca.addAll(cad);
            }
            condAdd = ca.toArray(new Tpl[0]);
        }

        boolean isAdl() {
            return residual != null || !conds.isEmpty();
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

    private void compileSchema(Action a, List<Normalizer.Lit> conj, Formula residual) {
        List<Normalizer.EffectLit> effs = new ArrayList<>();
        List<NumericTerm> costs = new ArrayList<>();
        List<Normalizer.CondEffect> conds = new ArrayList<>();
        normalizer.effects(a.effects(), Map.of(), effs, costs, conds);
        // A conjunction with a literal and its negation can never hold.
        Set<Formula.Atom> positive = new HashSet<>();
        for (Normalizer.Lit l : conj) if (l.atom() != null && l.positive()) positive.add(l.atom());
        for (Normalizer.Lit l : conj) if (l.atom() != null && !l.positive() && positive.contains(l.atom())) return;
        Schema s = new Schema(schemas.size(), a, conj, effs, costs, residual, conds);
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
        clock.tick();
        if (remaining == 0) {
            checkFreeParameters(s, b);
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

    /** Refuses, before enumerating them, more instances of unbound parameters than the memory holds. */
    private void checkFreeParameters(Schema s, int[] b) {
        int free = 0;
        for (int x : b) if (x < 0) free++;
        if (free == 0) return;
        int[] sizes = new int[free];
        int k = 0;
        for (int i = 0; i < b.length; i++) if (b[i] < 0) sizes[k++] = universe.ofTypes(s.params.get(i).types()).length;
        GroundingLimits.check("actions of '" + s.action + "'", GroundingLimits.log10Combinations(sizes),
                Math.max(1, GroundingLimits.maxActions() - ops.size()), free + " parameter" + (free == 1 ? "" : "s") + " no precondition binds, " + GroundingLimits.objects(sizes));
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

    static int value(int term, int[] b) {
        return term < 0 ? -(term + 1) : b[term];
    }

    static int[] args(Tpl t, int[] b) {
        int[] a = new int[t.terms.length];
        for (int i = 0; i < a.length; i++) a[i] = value(t.terms[i], b);
        return a;
    }

    private void instantiate(Schema s, int[] b) {
        clock.tick();
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
        int[] del = new int[s.del.length];
        for (int i = 0; i < del.length; i++) del[i] = factId(s.del[i].pred, args(s.del[i], b));
        double cost = 0;
        for (NumericTerm c : s.costs) cost += cost(c, s, b);
        String[] names = new String[b.length];
        for (int i = 0; i < b.length; i++) names[i] = universe.names.get(b[i]);
        if (!s.isAdl()) {
            addOp(s.action, names, sortedUnique(pre), sortedUnique(neg), add, del, cost, List.of());
            return;
        }
        Map<String, String> binding = new HashMap<>();
        for (int i = 0; i < b.length; i++) binding.put(s.params.get(i).name(), names[i]);
        List<GroundFormula.Conj> cases = s.residual == null
                ? List.of(new GroundFormula.Conj(new int[0], new int[0])) : groundFormula.dnf(s.residual, binding);
        List<List<GroundFormula.Conj>> condCases = new ArrayList<>();
        for (CondTpl c : s.conds) condCases.add(groundFormula.dnf(c.condition(), binding));
        for (GroundFormula.Conj k : cases) {
            int[] opPre = union(sortedUnique(pre), k.pos());
            int[] opNeg = union(sortedUnique(neg), k.neg());
            if (intersects(opPre, opNeg)) continue;
            List<Integer> allAdd = new ArrayList<>();
            for (int f : add) allAdd.add(f);
            List<Integer> allDel = new ArrayList<>();
            for (int f : del) allDel.add(f);
            List<GroundOp.When> whens = new ArrayList<>();
            for (int ci = 0; ci < s.conds.size(); ci++) {
                CondTpl c = s.conds.get(ci);
                int[] cAdd = new int[c.add().length];
                for (int i = 0; i < cAdd.length; i++) cAdd[i] = factId(c.add()[i].pred, args(c.add()[i], b));
                int[] cDel = new int[c.del().length];
                for (int i = 0; i < cDel.length; i++) cDel[i] = factId(c.del()[i].pred, args(c.del()[i], b));
                for (GroundFormula.Conj cc : condCases.get(ci)) {
                    // the operator's precondition decides parts of the condition
                    if (intersects(cc.pos(), opNeg) || intersects(cc.neg(), opPre)) continue;
                    int[] cPre = minus(cc.pos(), opPre);
                    int[] cNeg = minus(cc.neg(), opNeg);
                    if (cPre.length == 0 && cNeg.length == 0) {
                        for (int f : cAdd) allAdd.add(f);
                        for (int f : cDel) allDel.add(f);
                    } else {
                        whens.add(new GroundOp.When(cPre, cNeg, sortedUnique(cAdd), sortedUnique(cDel)));
                    }
                }
            }
            addOp(s.action, names, opPre, opNeg, allAdd.stream().mapToInt(Integer::intValue).toArray(),
                    allDel.stream().mapToInt(Integer::intValue).toArray(), cost, whens);
        }
    }

    /** Adds the operator (a fact both added and deleted unconditionally is only added) and queues what it can add. */
    private void addOp(String action, String[] names, int[] pre, int[] neg, int[] add, int[] del, double cost, List<GroundOp.When> whens) {
        int[] a = sortedUnique(add);
        int[] d = minus(sortedUnique(del), a);
        if (ops.size() >= GroundingLimits.maxActions()) {
            GroundingLimits.check("actions", Math.log10(ops.size() + 1.0), GroundingLimits.maxActions(), "reachable instances, and more to come");
        }
        ops.add(new GroundOp(action, names, pre, neg, a, d, cost, whens.isEmpty() ? null : whens.toArray(new GroundOp.When[0]), false));
        for (int f : a) enqueue(f);
        for (GroundOp.When w : whens) for (int f : w.add()) enqueue(f);
    }

    /** Sorted union of two sorted unique arrays. */
    static int[] union(int[] a, int[] b) {
        if (b.length == 0) return a;
        if (a.length == 0) return b;
        int[] c = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return sortedUnique(c);
    }

    /** Elements of sorted {@code a} not in sorted {@code b}. */
    static int[] minus(int[] a, int[] b) {
        if (b.length == 0 || a.length == 0) return a;
        int[] out = new int[a.length];
        int n = 0;
        for (int x : a) if (Arrays.binarySearch(b, x) < 0) out[n++] = x;
        return n == a.length ? a : Arrays.copyOf(out, n);
    }

    static boolean intersects(int[] a, int[] b) {
        for (int x : a) if (Arrays.binarySearch(b, x) >= 0) return true;
        return false;
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
