package org.triad.planner;

import java.util.ArrayList;
import java.util.List;

/**
 * The search-time view of a grounded problem: operators as int arrays over fact ids, with the
 * indexes heuristics and successor generation need. States are sorted int arrays of true facts.
 */
final class SearchTask {
    final int numFacts;
    final GroundOp[] ops;
    final int[][] pre;
    final int[][] neg;
    final int[][] add;
    final int[][] del;
    /** Conditional effects per operator, null for an operator without any. */
    final GroundOp.When[][] when;
    /** Whether any operator has conditional effects (then the special STRIPS searches do not apply). */
    final boolean hasConditionalEffects;
    /** The operators as the delete relaxation sees them (conditional effects split off). */
    final RelaxedOps relaxed;
    /** The rules of derived predicates, null without any (then states hold basic facts only). */
    final Axioms axioms;

    int ruleCount() {
        return axioms == null ? 0 : axioms.head.length;
    }
    /** Operators having the fact as a positive precondition. */
    final int[][] preOf;
    /**
     * Operators triggered for applicability tests by one precondition: the one of the predicate with
     * the most ground facts (ties: the first), since one of many alternatives (a piece on one of a
     * hundred squares) is true in fewer states than one of few (a square clear), so fewer operators
     * are tried in vain (tetris p026: trying operators was 61% of the CPU when the first precondition
     * triggered them).
     */
    final int[][] triggeredBy;
    /**
     * Per fact, how many operators have it as their first precondition: the work {@link Successors}
     * counts per true fact, as when those triggered the tests, so the work meter, and with it every
     * budget and plan, is what it was.
     */
    final int[] firstPreCount;
    final int[] noPre;
    final Grounder grounder;
    private int[][] addOf;
    private int[][] delOf;
    /** Relevant sub-tasks by their operator set: successive goals often need the same operators. */
    private final java.util.Map<java.util.BitSet, SearchTask> subtasks = new java.util.LinkedHashMap<>(16, 0.75f, true);
    /** Scratch space (heuristic and successor arrays) reused by the next solve that takes it. */
    private final java.util.concurrent.atomic.AtomicReference<Scratch> scratch = new java.util.concurrent.atomic.AtomicReference<>();

    private volatile CompressedGraphSearch.Structure graphStructure;

    /** The token-graph split of this task, computed once (successive goals reuse the task). */
    CompressedGraphSearch.Structure graphStructure() {
        CompressedGraphSearch.Structure gs = graphStructure;
        if (gs == null) {
            gs = CompressedGraphSearch.structure(this);
            graphStructure = gs;
        }
        return gs;
    }

    /** The heuristics and successor generator one solve uses; the h^add one is made when first needed. */
    record Scratch(FfHeuristic heuristic, Successors successors, AdditiveFfHeuristic[] additiveHolder) {
        AdditiveFfHeuristic additive(SearchTask task) {
            if (additiveHolder[0] == null) additiveHolder[0] = new AdditiveFfHeuristic(task);
            return additiveHolder[0];
        }
    }

    Scratch takeScratch() {
        Scratch s = scratch.getAndSet(null);
        return s != null ? s : new Scratch(new FfHeuristic(this), new Successors(this), new AdditiveFfHeuristic[1]);
    }

    void returnScratch(Scratch s) {
        scratch.set(s);
    }

    SearchTask(Grounder grounder, List<GroundOp> opList, int numFacts) {
        this.grounder = grounder;
        this.numFacts = numFacts;
        List<GroundOp> actions = new ArrayList<>(opList.size());
        List<GroundOp> rules = new ArrayList<>();
        for (GroundOp o : opList) (o.isAxiom() ? rules : actions).add(o);
        if (rules.isEmpty()) {
            axioms = null;
        } else {
            boolean[] derivedFact = new boolean[numFacts];
            for (int f = 0; f < numFacts; f++) derivedFact[f] = grounder.isDerivedFact(f);
            List<Integer> strata = new ArrayList<>(rules.size());
            for (GroundOp r : rules) strata.add(grounder.stratum[grounder.facts.get(r.add()[0])[0]]);
            axioms = new Axioms(rules, strata, derivedFact);
        }
        ops = actions.toArray(new GroundOp[0]);
        int n = ops.length;
        pre = new int[n][];
        neg = new int[n][];
        add = new int[n][];
        del = new int[n][];
        when = new GroundOp.When[n][];
        boolean conditional = false;
        int[] preCount = new int[numFacts];
        int[] firstCount = new int[numFacts];
        List<Integer> none = new ArrayList<>();
        for (int o = 0; o < n; o++) {
            pre[o] = ops[o].pre();
            neg[o] = ops[o].neg();
            add[o] = ops[o].add();
            del[o] = ops[o].del();
            when[o] = ops[o].when();
            conditional |= when[o] != null;
            for (int f : pre[o]) preCount[f]++;
            if (pre[o].length == 0) none.add(o); else firstCount[pre[o][0]]++;
        }
        firstPreCount = firstCount;
        // ground facts per predicate (a fact the grounder does not list, such as a compiled one: 0)
        int[] predicateOf = new int[numFacts];
        java.util.Arrays.fill(predicateOf, -1);
        java.util.Map<Integer, Integer> factsOfPredicate = new java.util.HashMap<>();
        for (int f = 0; f < numFacts && grounder != null && f < grounder.facts.size(); f++) {
            predicateOf[f] = grounder.facts.get(f)[0];
            factsOfPredicate.merge(predicateOf[f], 1, Integer::sum);
        }
        int[] trigger = new int[n];
        int[] triggerCount = new int[numFacts];
        for (int o = 0; o < n; o++) {
            if (pre[o].length == 0) continue;
            int best = pre[o][0];
            int bestSize = predicateOf[best] < 0 ? 0 : factsOfPredicate.get(predicateOf[best]);
            for (int f : pre[o]) {
                int size = predicateOf[f] < 0 ? 0 : factsOfPredicate.get(predicateOf[f]);
                if (size > bestSize) {
                    best = f;
                    bestSize = size;
                }
            }
            trigger[o] = best;
            triggerCount[best]++;
        }
        preOf = new int[numFacts][];
        triggeredBy = new int[numFacts][];
        for (int f = 0; f < numFacts; f++) {
            preOf[f] = new int[preCount[f]];
            triggeredBy[f] = new int[triggerCount[f]];
        }
        int[] fill = new int[numFacts];
        int[] fill2 = new int[numFacts];
        for (int o = 0; o < n; o++) {
            for (int f : pre[o]) preOf[f][fill[f]++] = o;
            if (pre[o].length > 0) triggeredBy[trigger[o]][fill2[trigger[o]]++] = o;
        }
        noPre = none.stream().mapToInt(Integer::intValue).toArray();
        hasConditionalEffects = conditional;
        relaxed = new RelaxedOps(this);
    }

    /** Per operator, its unconditional adds (or deletes) followed by its conditional ones. */
    private int[][] withConditional(int[][] lists, boolean adds) {
        if (!hasConditionalEffects) return lists;
        int[][] out = new int[lists.length][];
        for (int o = 0; o < lists.length; o++) {
            out[o] = lists[o];
            if (when[o] == null) continue;
            for (GroundOp.When w : when[o]) out[o] = Grounder.union(out[o], adds ? w.add() : w.del());
        }
        return out;
    }

    private static int[][] invert(int[][] lists, int numFacts) {
        int[] count = new int[numFacts];
        for (int[] l : lists) for (int f : l) count[f]++;
        int[][] out = new int[numFacts][];
        for (int f = 0; f < numFacts; f++) out[f] = new int[count[f]];
        int[] fill = new int[numFacts];
        for (int o = 0; o < lists.length; o++) for (int f : lists[o]) out[f][fill[f]++] = o;
        return out;
    }

    /**
     * The operators that can matter for the goal (backward relevance): achievers of relevant facts
     * and deleters of facts that must be false (negative goals and preconditions), closed under
     * their preconditions. Any plan stays a plan after dropping the other operators, so search and
     * heuristic only need these.
     */
    synchronized SearchTask relevantTo(int[] goalPos, int[] goalNeg) {
        // a rule's negative conditions make every fact it reads matter both ways: keep the whole task
        if (axioms != null) return this;
        if (addOf == null) {
            addOf = invert(withConditional(add, true), numFacts);
            delOf = invert(withConditional(del, false), numFacts);
        }
        boolean[] posRel = new boolean[numFacts];
        boolean[] negRel = new boolean[numFacts];
        boolean[] opRel = new boolean[ops.length];
        int[] stack = new int[2 * numFacts + 2];
        int sp = 0;
        for (int g : goalPos) if (!posRel[g]) { posRel[g] = true; stack[sp++] = g; }
        for (int g : goalNeg) if (!negRel[g]) { negRel[g] = true; stack[sp++] = ~g; }
        int count = 0;
        while (sp > 0) {
            int x = stack[--sp];
            int[] ops = x >= 0 ? addOf[x] : delOf[~x];
            for (int o : ops) {
                if (opRel[o]) continue;
                opRel[o] = true;
                count++;
                for (int p : pre[o]) if (!posRel[p]) { posRel[p] = true; stack[sp++] = p; }
                for (int p : neg[o]) if (!negRel[p]) { negRel[p] = true; stack[sp++] = ~p; }
                if (when[o] == null) continue;
                // a condition's facts must keep their values exactly, so both their achievers and deleters stay
                for (GroundOp.When w : when[o]) {
                    for (int[] facts : new int[][] {w.pre(), w.neg()}) {
                        for (int p : facts) {
                            if (!posRel[p]) { posRel[p] = true; stack[sp++] = p; }
                            if (!negRel[p]) { negRel[p] = true; stack[sp++] = ~p; }
                        }
                    }
                }
            }
        }
        if (count == ops.length) return this;
        java.util.BitSet key = new java.util.BitSet(ops.length);
        for (int o = 0; o < ops.length; o++) if (opRel[o]) key.set(o);
        SearchTask cached = subtasks.get(key);
        if (cached != null) return cached;
        List<GroundOp> kept = new ArrayList<>(count);
        for (int o = 0; o < ops.length; o++) if (opRel[o]) kept.add(ops[o]);
        SearchTask sub = new SearchTask(grounder, kept, numFacts);
        subtasks.put(key, sub);
        if (subtasks.size() > 16) subtasks.remove(subtasks.keySet().iterator().next());
        return sub;
    }
}
