package org.triad.planner;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * Metric-FF's numeric relaxation as a distance estimate: a relaxed planning graph whose facts are never
 * deleted and whose fluents are intervals [lo, hi] that every applicable action widens by its numeric
 * effects, layer by layer (so a battery that a recharge raises by 10 reaches 100 from 40 in six layers).
 * The estimate is the sum over the goal's conjuncts of the first layer at which each can hold
 * (additive, like h_add over layers); {@link #DEAD_END} when the graph stops growing first.
 */
final class NumericHeuristic {
    static final int DEAD_END = Integer.MAX_VALUE;
    /** Layers after which a goal still out of reach counts as very far (growth may go on forever). */
    private static final int MAX_LAYERS = 2_000;

    private final NumericTask task;
    private final List<NumericTask.Cond> goals = new ArrayList<>();

    /** Per operator, how much it makes the metric grow (its unconditional accumulator effects, valued in the initial state; at least 0). */
    private final double[] opCost;
    /** The least positive {@link #opCost}: the price of a step a numeric condition still needs. */
    private final double cheapest;
    private final boolean metricOnlyGrows;
    /**
     * Per fluent: whether a smaller lower bound, or a larger upper bound, can make any condition true
     * (a battery that only has to be at least the next road's length gains nothing from going lower).
     * Growth in no such direction cannot reach the goal, so the graph has then stopped growing: without
     * this a robot with too little charge to reach a dock had its estimate run to {@link #MAX_LAYERS}.
     */
    private final boolean[] lowMatters;
    private final boolean[] highMatters;
    /** Per operator: whether all its effects are unconditional and change no fluent the relaxation tracks. */
    private final boolean[] pure;

    NumericHeuristic(NumericTask task) {
        this.task = task;
        if (task.goal instanceof NumericTask.All a) goals.addAll(a.parts());
        else goals.add(task.goal);
        opCost = new double[task.ops.size()];
        boolean grows = task.metric != null;
        for (int f = 0; f < task.fluentNames.size() && grows; f++) {
            if (NumericTask.mentions(task.metric, f) && (!task.accumulator[f] || task.metricWeight[f] < 0)) grows = false;
        }
        double least = Double.POSITIVE_INFINITY;
        for (int o = 0; o < task.ops.size(); o++) {
            double c = 0;
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (NumericTask.NumEffect n : e.numeric()) {
                    double w = task.metricWeight[n.fluent()];
                    if (w == 0) continue;
                    double amount = NumericTask.value(n.value(), task.initValues);
                    double delta = w * (n.kind().equals("decrease") ? -amount : amount);
                    if (!(n.value() instanceof NumericTask.Num) || delta < 0) grows = false;
                    if (e.when() == NumericTask.TRUE && Double.isFinite(delta)) c += delta;
                }
            }
            opCost[o] = Math.max(0, c);
            if (opCost[o] > 0) least = Math.min(least, opCost[o]);
        }
        cheapest = least == Double.POSITIVE_INFINITY ? 0 : least;
        int nv = task.fluentNames.size();
        lowMatters = new boolean[nv];
        highMatters = new boolean[nv];
        for (int i = 0; i < nv; i++) {
            lowThresholds.add(new ArrayList<>());
            highThresholds.add(new ArrayList<>());
        }
        directions(task.goal);
        for (NumericTask.Op op : task.ops) {
            directions(op.pre());
            for (NumericTask.Effects e : op.effects()) {
                directions(e.when());
                for (NumericTask.NumEffect n : e.numeric()) {
                    // a value an effect adds or assigns: any of its bounds may matter
                    sign(n.value(), 0, lowMatters, highMatters);
                    if (n.kind().startsWith("scale")) lowMatters[n.fluent()] = highMatters[n.fluent()] = true;
                }
            }
        }
        lowestThreshold = new double[nv];
        highestThreshold = new double[nv];
        for (int i = 0; i < nv; i++) {
            lowestThreshold[i] = lowThresholds.get(i).stream().mapToDouble(Double::doubleValue).min().orElse(Double.POSITIVE_INFINITY);
            highestThreshold[i] = highThresholds.get(i).stream().mapToDouble(Double::doubleValue).max().orElse(Double.NEGATIVE_INFINITY);
        }
        pure = new boolean[task.ops.size()];
        for (int o = 0; o < pure.length; o++) {
            boolean p = true;
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                if (e.when() != NumericTask.TRUE) p = false;
                for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) p = false;
            }
            pure[o] = p;
        }
        metricOnlyGrows = grows;
        int no = task.ops.size();
        preFacts = new int[no][];
        preRest = new NumericTask.Cond[no];
        repeatAlways = new boolean[no];
        raises = new NumericTask.NumEffect[no][];
        lowers = new NumericTask.NumEffect[no][];
        boolean anyChoice = false;
        List<List<Integer>> byFact = new ArrayList<>();
        for (int f = 0; f < task.factNames.size(); f++) byFact.add(new ArrayList<>());
        for (int o = 0; o < no; o++) {
            NumericTask.Op op = task.ops.get(o);
            java.util.TreeSet<Integer> fs = new java.util.TreeSet<>();
            List<NumericTask.Cond> rest = new ArrayList<>();
            for (NumericTask.Cond c : op.pre() instanceof NumericTask.All a ? a.parts() : List.of(op.pre())) {
                if (c instanceof NumericTask.Fact f && f.positive()) fs.add(f.id());
                else if (!(c instanceof NumericTask.Fact)) rest.add(c); // a negative fact holds in the relaxation
                if (c instanceof NumericTask.Any) anyChoice = true;
            }
            preFacts[o] = fs.stream().mapToInt(Integer::intValue).toArray();
            for (int f : preFacts[o]) byFact.get(f).add(o);
            preRest[o] = rest.isEmpty() ? NumericTask.TRUE : rest.size() == 1 ? rest.get(0) : new NumericTask.All(rest);
            List<NumericTask.NumEffect> up = new ArrayList<>();
            List<NumericTask.NumEffect> down = new ArrayList<>();
            for (NumericTask.Effects e : op.effects()) {
                if (e.when() != NumericTask.TRUE) {
                    repeatAlways[o] = true;
                    anyChoice = true;
                }
                for (NumericTask.NumEffect n : e.numeric()) {
                    if (task.accumulator[n.fluent()]) continue;
                    if (!(n.value() instanceof NumericTask.Num k) || n.kind().startsWith("scale")) repeatAlways[o] = true;
                    else if (n.kind().equals("assign") || k.value() == 0) continue; // the same interval again: nothing more to give
                    else if (n.kind().equals("increase") == k.value() > 0) up.add(n);
                    else down.add(n);
                }
            }
            raises[o] = up.toArray(new NumericTask.NumEffect[0]);
            lowers[o] = down.toArray(new NumericTask.NumEffect[0]);
        }
        factOps = new int[byFact.size()][];
        for (int f = 0; f < factOps.length; f++) factOps[f] = byFact.get(f).stream().mapToInt(Integer::intValue).toArray();
        choices = anyChoice;
        java.util.TreeSet<Integer> gf = new java.util.TreeSet<>();
        collectFacts(task.goal, gf);
        goalFacts = gf.stream().mapToInt(Integer::intValue).toArray();
        isGoalFact = new boolean[task.factNames.size()];
        for (int f : goalFacts) isGoalFact[f] = true;
        projection = new ProjectionBound(task, preFacts, goals);
    }

    /** Adds a delivery's legs to {@link #lowerBound} (h_max over the facts sees only the longer). */
    private final ProjectionBound projection;

    /** The facts the goal mentions (positively, anywhere in it), whose costs the cost estimates need. */
    private final int[] goalFacts;
    private final boolean[] isGoalFact;

    private static void collectFacts(NumericTask.Cond c, java.util.Set<Integer> out) {
        if (c instanceof NumericTask.Fact f && f.positive()) out.add(f.id());
        else if (c instanceof NumericTask.All a) a.parts().forEach(p -> collectFacts(p, out));
        else if (c instanceof NumericTask.Any a) a.parts().forEach(p -> collectFacts(p, out));
    }

    /** Per operator: its positive fact preconditions (the triggers of the relaxed graph) and the rest of its precondition. */
    private final int[][] preFacts;
    private final NumericTask.Cond[] preRest;
    /** Per fact: the operators that need it. */
    private final int[][] factOps;
    /**
     * Per operator, how it widens the intervals again in every layer after its first: conditional or
     * non-constant effects ({@code repeatAlways}) each time, a constant increase only the upper bound
     * ({@code raises}), a constant decrease only the lower ({@code lowers}); a constant assignment gives the
     * same interval again, so nothing.
     */
    private final boolean[] repeatAlways;
    private final NumericTask.NumEffect[][] raises;
    private final NumericTask.NumEffect[][] lowers;
    /** Whether some precondition or effect condition is a disjunction, or an effect conditional (the cost estimate then keeps its layered sums). */
    private final boolean choices;

    /**
     * The layer estimate: the sum over the goal's conjuncts of the first layer of the numeric relaxed
     * planning graph at which each can hold, {@link #DEAD_END} when the graph stops growing first. The
     * graph is built as FF builds its STRIPS one: an operator is looked at when its last fact precondition
     * appears (then in every layer until its comparisons hold), and an applied one widens the intervals
     * again only in directions that can still make a condition true ({@link #matters}: a battery's falling
     * lower bound, once below every threshold of a {@code <} comparison, changes nothing). Equal to
     * {@link #estimateByLayers}, in time about linear in the operators instead of operators times layers.
     */
    int estimate(BitSet facts, double[] values) {
        return layers(facts, values, null, null, -1);
    }

    /**
     * The graph of {@link #estimate} for {@link NumericRelaxedPlan}: fills the first layer each operator
     * applies and each goal conjunct holds (-1: not reached); returns the estimate or {@link #DEAD_END}.
     */
    int explore(BitSet facts, double[] values, int[] opLayer, int[] goalLayer) {
        return layers(facts, values, opLayer, goalLayer, -1);
    }

    /** The goal's conjuncts, in the order {@link #explore} numbers them. */
    List<NumericTask.Cond> goals() {
        return goals;
    }

    /** An operator's positive fact preconditions. */
    int[] preFacts(int o) {
        return preFacts[o];
    }

    /** The rest of an operator's precondition (its comparisons, disjunctions). */
    NumericTask.Cond preRest(int o) {
        return preRest[o];
    }

    /**
     * The graph of {@link #estimate}; {@code opLayer}/{@code goalLayer} (when given) get the first layer each
     * operator applies / each goal conjunct holds (-1: not reached). With {@code after} at least 0 the graph
     * goes on for that many layers after the goal holds, without widening any further, and returns 0
     * (or {@link #DEAD_END}).
     */
    private int layers(BitSet facts, double[] values, int[] opLayer, int[] goalLayer, int after) {
        ranOut = false;
        int no = task.ops.size();
        BitSet reached = (BitSet) facts.clone();
        double[] lo = values.clone();
        double[] hi = values.clone();
        int[] missing = new int[no];
        int[] cand = new int[no];
        int nc = 0;
        int[] repeat = new int[no];
        int nr = 0;
        for (int o = 0; o < no; o++) {
            int m = 0;
            for (int f : preFacts[o]) if (!facts.get(f)) m++;
            missing[o] = m;
            if (m == 0) cand[nc++] = o;
        }
        int[] added = new int[task.factNames.size()];
        boolean[] done = new boolean[goals.size()];
        int open = goals.size();
        int sum = 0;
        boolean checkedOptimistically = false;
        boolean numbersChanged;
        BitSet pending = new BitSet();
        int allReachedAt = -1;
        for (int layer = 0; layer <= MAX_LAYERS; layer++) {
            for (int g = 0; g < goals.size(); g++) {
                if (!done[g] && holds(goals.get(g), reached, lo, hi)) {
                    done[g] = true;
                    open--;
                    sum += layer;
                    if (goalLayer != null) goalLayer[g] = layer;
                }
            }
            if (open == 0 && allReachedAt < 0) {
                if (after < 0) return sum;
                allReachedAt = layer;
            }
            if (allReachedAt >= 0 && layer > allReachedAt + after) return 0;
            boolean widening = allReachedAt < 0;
            double[] nextLo = lo.clone();
            double[] nextHi = hi.clone();
            int na = 0;
            int firedFrom = nr;
            int kept = 0;
            for (int i = 0; i < nc; i++) {
                int o = cand[i];
                if (preRest[o] != NumericTask.TRUE && !holds(preRest[o], reached, lo, hi)) {
                    cand[kept++] = o;
                    continue;
                }
                if (opLayer != null) opLayer[o] = layer;
                na = apply(o, reached, pending, lo, hi, nextLo, nextHi, added, na, widening);
                if (repeatAlways[o] || raises[o].length > 0 || lowers[o].length > 0) repeat[nr++] = o;
            }
            nc = kept;
            if (widening) {
                int live = 0;
                for (int i = 0; i < nr; i++) {
                    int o = repeat[i];
                    if (i >= firedFrom) {
                        repeat[live++] = o; // fired in this layer: its effects are in already
                        continue;
                    }
                    if (repeatAlways[o]) {
                        na = apply(o, reached, pending, lo, hi, nextLo, nextHi, added, na, true);
                        repeat[live++] = o;
                        continue;
                    }
                    // a direction that cannot help now never can (bounds only widen): an operator left with none is dropped
                    boolean helps = false;
                    for (NumericTask.NumEffect n : raises[o]) {
                        if (raiseHelps(n.fluent(), hi)) {
                            widen(n, lo, hi, nextLo, nextHi);
                            helps = true;
                        }
                    }
                    for (NumericTask.NumEffect n : lowers[o]) {
                        if (lowerHelps(n.fluent(), lo)) {
                            widen(n, lo, hi, nextLo, nextHi);
                            helps = true;
                        }
                    }
                    if (helps) repeat[live++] = o;
                }
                nr = live;
            }
            boolean changed = na > 0;
            numbersChanged = false;
            for (int i = 0; i < lo.length && !numbersChanged; i++) numbersChanged = matters(i, lo, hi, nextLo, nextHi);
            changed |= numbersChanged;
            if (!changed) return after >= 0 && allReachedAt >= 0 ? 0 : DEAD_END;
            if (na == 0 && !checkedOptimistically && allReachedAt < 0) {
                // (with after, too, while a goal is open: a goal out of this reach never holds, so the graph
                // would end in DEAD_END all the same, only later)
                // only numbers still grow, perhaps forever: a goal that needs a fact no action can add is out of reach
                checkedOptimistically = true;
                if (!optimisticallyReachable(reached, done)) return DEAD_END;
            }
            for (int i = 0; i < na; i++) {
                int f = added[i];
                reached.set(f);
                pending.clear(f);
                for (int o : factOps[f]) if (--missing[o] == 0) cand[nc++] = o;
            }
            lo = nextLo;
            hi = nextHi;
        }
        ranOut = true;
        return after >= 0 ? (open == 0 ? 0 : DEAD_END) : sum + open * MAX_LAYERS;
    }

    /** Whether the last {@link #layers} ended at {@link #MAX_LAYERS} (its DEAD_END is then not the layer estimate's). */
    private boolean ranOut;

    /** Applies an operator's effects to the next layer; returns the new count of {@code added}. */
    private int apply(int o, BitSet reached, BitSet pending, double[] lo, double[] hi, double[] nextLo, double[] nextHi, int[] added, int na, boolean widening) {
        for (NumericTask.Effects e : task.ops.get(o).effects()) {
            if (e.when() != NumericTask.TRUE && !holds(e.when(), reached, lo, hi)) continue;
            for (int f : e.adds()) {
                if (!reached.get(f) && !pending.get(f)) {
                    pending.set(f);
                    added[na++] = f;
                }
            }
            if (widening) for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) widen(n, lo, hi, nextLo, nextHi);
        }
        return na;
    }

    /** Whether raising fluent {@code i}'s upper bound can still make a condition true ({@link #matters}). */
    private boolean raiseHelps(int i, double[] hi) {
        return highMatters[i] || Double.isNaN(hi[i]) || highestThreshold[i] >= hi[i];
    }

    private boolean lowerHelps(int i, double[] lo) {
        return lowMatters[i] || Double.isNaN(lo[i]) || lowestThreshold[i] <= lo[i];
    }

    /** Per fluent: the values at which a comparison of it alone flips, for its lower and its upper bound. */
    private final List<List<Double>> lowThresholds = new ArrayList<>();
    private final List<List<Double>> highThresholds = new ArrayList<>();
    /** Per fluent, the least of its lower bound's thresholds and the greatest of its upper bound's (a bound is ahead of some threshold iff it is ahead of these). */
    private final double[] lowestThreshold;
    private final double[] highestThreshold;

    /**
     * Whether the widening of fluent {@code i} can make a condition true: its first value, a bound that
     * matters in general ({@link #lowMatters}), or one that moves towards a threshold of a comparison of it
     * alone that it has not yet passed (a threshold passed already gains nothing from going further).
     */
    private boolean matters(int i, double[] lo, double[] hi, double[] nextLo, double[] nextHi) {
        if (Double.isNaN(lo[i])) return !Double.isNaN(nextLo[i]);
        // a threshold still ahead, not only one crossed now
        if (nextLo[i] < lo[i] && (lowMatters[i] || lowestThreshold[i] <= lo[i])) return true;
        return nextHi[i] > hi[i] && (highMatters[i] || highestThreshold[i] >= hi[i]);
    }

    /** The one fluent a linear expression reads, -1 when it reads none, -2 when several or not linearly. */
    private static int single(NumericTask.Expr e) {
        if (e instanceof NumericTask.Num) return -1;
        if (e instanceof NumericTask.Var v) return v.fluent();
        if (e instanceof NumericTask.Neg n) return single(n.operand());
        NumericTask.Bin b = (NumericTask.Bin) e;
        int l = single(b.left());
        int r = single(b.right());
        if (l == -2 || r == -2) return -2;
        if (b.op() == '*' && l >= 0 && r >= 0) return -2;
        if (b.op() == '/' && r >= 0) return -2;
        if (l >= 0 && r >= 0 && l != r) return -2;
        return Math.max(l, r);
    }

    private void directions(NumericTask.Cond c) {
        if (c instanceof NumericTask.All a) a.parts().forEach(this::directions);
        else if (c instanceof NumericTask.Any a) a.parts().forEach(this::directions);
        else if (c instanceof NumericTask.Cmp m && single(new NumericTask.Bin('-', m.left(), m.right())) >= 0) {
            // one fluent x, linearly: d(x) = k x + c op 0 flips at x = -c / k; only crossing that matters
            NumericTask.Expr d = new NumericTask.Bin('-', m.left(), m.right());
            int f = single(d);
            double[] at = new double[lowMatters.length];
            double c0 = NumericTask.value(d, at);
            at[f] = 1;
            double k = NumericTask.value(d, at) - c0;
            if (k == 0 || !Double.isFinite(k) || !Double.isFinite(c0)) {
                lowMatters[f] = highMatters[f] = true;
                return;
            }
            double t = -c0 / k;
            int dir = switch (m.op()) {
                case ">", ">=" -> k > 0 ? 1 : -1;
                case "<", "<=" -> k > 0 ? -1 : 1;
                default -> 0;
            };
            if (dir >= 0) highThresholds.get(f).add(t);
            if (dir <= 0) lowThresholds.get(f).add(t);
        } else if (c instanceof NumericTask.Cmp m) {
            // left - right op 0: '>' and '>=' get easier as it grows, '<' and '<=' as it falls, '=' either way
            int dir = switch (m.op()) {
                case ">", ">=" -> 1;
                case "<", "<=" -> -1;
                default -> 0;
            };
            sign(m.left(), dir, lowMatters, highMatters);
            sign(m.right(), -dir, lowMatters, highMatters);
        }
    }

    /**
     * Marks, for each fluent in {@code e}, which bound helps when {@code e} should grow ({@code dir} 1),
     * fall (-1) or either (0); outside linear arithmetic both bounds count.
     */
    private static void sign(NumericTask.Expr e, int dir, boolean[] low, boolean[] high) {
        if (e instanceof NumericTask.Var v) {
            if (dir >= 0) high[v.fluent()] = true;
            if (dir <= 0) low[v.fluent()] = true;
        } else if (e instanceof NumericTask.Neg n) {
            sign(n.operand(), -dir, low, high);
        } else if (e instanceof NumericTask.Bin b) {
            switch (b.op()) {
                case '+' -> {
                    sign(b.left(), dir, low, high);
                    sign(b.right(), dir, low, high);
                }
                case '-' -> {
                    sign(b.left(), dir, low, high);
                    sign(b.right(), -dir, low, high);
                }
                case '*' -> {
                    if (b.left() instanceof NumericTask.Num k) sign(b.right(), k.value() >= 0 ? dir : -dir, low, high);
                    else if (b.right() instanceof NumericTask.Num k) sign(b.left(), k.value() >= 0 ? dir : -dir, low, high);
                    else {
                        sign(b.left(), 0, low, high);
                        sign(b.right(), 0, low, high);
                    }
                }
                default -> {
                    if (b.right() instanceof NumericTask.Num k) sign(b.left(), k.value() >= 0 ? dir : -dir, low, high);
                    else {
                        sign(b.left(), 0, low, high);
                        sign(b.right(), 0, low, high);
                    }
                }
            }
        }
    }

    /** Whether no step can make the metric smaller (so a partial plan as costly as a found one can be pruned). */
    boolean metricOnlyGrows() {
        return metricOnlyGrows;
    }

    /**
     * A cost-sensitive estimate for the metric: h_add over the same layered numeric relaxation, each
     * operator costing its {@link #opCost} plus its fact preconditions' costs, and a numeric condition
     * not yet true in the state the {@link #cheapest} step per layer it needs. Without action costs in
     * the metric it is the layer estimate. Not admissible; it orders weighted A* by cost.
     */
    double estimateCost(BitSet facts, double[] values) {
        return estimateCost(facts, values, null);
    }

    /**
     * {@link #estimateCost}; {@code layerEstimate[0]} (when given) gets {@link #estimate}'s value when the
     * same graph gave it (-1 when not): until the goal holds the cost graph is the layer estimate's, so
     * a search that wants both builds one graph, not two.
     */
    double estimateCost(BitSet facts, double[] values, int[] layerEstimate) {
        if (layerEstimate != null) layerEstimate[0] = -1;
        if (cheapest == 0) {
            int h = estimate(facts, values);
            if (layerEstimate != null) layerEstimate[0] = h;
            return h == DEAD_END ? Double.POSITIVE_INFINITY : h;
        }
        if (choices) return estimateCostByLayers(facts, values);
        int no = task.ops.size();
        int[] opLayer = new int[no];
        java.util.Arrays.fill(opLayer, -1);
        int[] goalLayer = new int[goals.size()];
        java.util.Arrays.fill(goalLayer, -1);
        if (layers(facts, values, opLayer, goalLayer, COST_LAYERS_AFTER) == DEAD_END) {
            // a graph that stopped growing with a goal open is the layer estimate's too, up to there
            if (layerEstimate != null && !ranOut) layerEstimate[0] = DEAD_END;
            return Double.POSITIVE_INFINITY;
        }
        if (layerEstimate != null) {
            // every goal reached: the sum of their first layers is what estimate returns (its graph is this
            // one up to that layer); a goal out of reach is left to estimate itself
            int sum = 0;
            for (int l : goalLayer) {
                if (l < 0) {
                    sum = -1;
                    break;
                }
                sum += l;
            }
            layerEstimate[0] = sum;
        }
        double[] own = new double[no];
        for (int o = 0; o < no; o++) {
            if (opLayer[o] >= 0) own[o] = opCost[o] + (numericHolds(preRest[o], values) ? 0 : cheapest * Math.max(1, opLayer[o]));
        }
        double[] fcost = factCosts(facts, opLayer, own, false);
        double sum = 0;
        for (int g = 0; g < goals.size(); g++) {
            NumericTask.Cond c = goals.get(g);
            sum += factCost(c, fcost) + (numericHolds(c, values) ? 0 : cheapest * Math.max(1, goalLayer[g]));
        }
        return sum;
    }

    /** Layers the cost estimate's graph goes on after the goal holds (cheaper supporters may appear later). */
    private static final int COST_LAYERS_AFTER = 8;

    /**
     * A lower bound on the metric's growth from this state to a goal state ({@code unit}: on the number
     * of steps): h_max over the facts, each operator costing its {@link #opCost} (1), comparisons and
     * effect conditions taken as true. Admissible for the steps always, for the metric when
     * {@link #metricOnlyGrows()} (every operator's growth is then a constant, at least 0); so a partial
     * plan whose cost plus this bound reaches the best plan's cost cannot improve on it. Infinite when no
     * relaxed plan reaches the goal's facts.
     */
    double lowerBound(BitSet facts, double[] values, boolean unit) {
        if (projection.coversGoal()) {
            // lookups, as cheap as the cache and reading the state's charge: neither cached nor counted as
            // computed (the budgets that count those stay for h_max's)
            return projection.bound(facts, values, unit ? unitCosts() : opCost);
        }
        java.util.Map<BitSet, Double> cache = unit ? unitBounds : costBounds;
        Double known = cache.get(facts);
        if (known != null) return known;
        double h = computeLowerBound(facts, unit);
        computed++;
        if (cache.size() < CACHED_BOUNDS) cache.put((BitSet) facts.clone(), h);
        return h;
    }

    /**
     * h_add over the facts, each operator costing its {@link #opCost} (1 with {@code unit}), comparisons
     * taken as true: not admissible, but it sees that a delivery needs the way to the item and the way on;
     * cached by the facts as {@link #lowerBound} is.
     */
    double additive(BitSet facts, boolean unit) {
        java.util.Map<BitSet, Double> cache = unit ? unitSums : costSums;
        Double known = cache.get(facts);
        if (known != null) return known;
        double[] fcost = factCosts(facts, null, unit ? unitCosts() : opCost, false);
        double h = 0;
        for (NumericTask.Cond c : goals) if (c instanceof NumericTask.Fact f && f.positive()) h += fcost[f.id()];
        computed++;
        if (cache.size() < CACHED_BOUNDS) cache.put((BitSet) facts.clone(), h);
        return h;
    }

    private final java.util.Map<BitSet, Double> unitSums = new java.util.HashMap<>();
    private final java.util.Map<BitSet, Double> costSums = new java.util.HashMap<>();

    /** Whether the goal needs some fact (else estimates over the facts alone see nothing of the way). */
    boolean goalHasFacts() {
        return goalFacts.length > 0;
    }

    /** How many bounds were computed rather than looked up (a work count for budgets). */
    long boundsComputed() {
        return computed;
    }

    private long computed;

    /** The bound depends on the facts alone: a robot's places and loads are few, its charge levels many. */
    private final java.util.Map<BitSet, Double> unitBounds = new java.util.HashMap<>();
    private final java.util.Map<BitSet, Double> costBounds = new java.util.HashMap<>();
    private static final int CACHED_BOUNDS = 500_000;

    private double computeLowerBound(BitSet facts, boolean unit) {
        double[] own = unit ? unitCosts() : opCost;
        double[] fcost = factCosts(facts, null, own, true);
        double h = 0;
        for (NumericTask.Cond c : goals) if (c instanceof NumericTask.Fact f && f.positive()) h = Math.max(h, fcost[f.id()]);
        // both are lower bounds on the same cost, so their maximum is one
        if (h < Double.POSITIVE_INFINITY && projection.applies()) h = Math.max(h, projection.bound(facts, null, own)); // by the facts alone: it is cached by them
        return h;
    }

    private double[] unitCosts;

    private double[] unitCosts() {
        if (unitCosts == null) {
            unitCosts = new double[task.ops.size()];
            java.util.Arrays.fill(unitCosts, 1);
        }
        return unitCosts;
    }

    /**
     * Facts' costs by a generalised Dijkstra: an operator (of those with {@code opLayer} at least 0, all
     * when it is null) adds its facts at its {@code own} cost plus the sum ({@code max}: the largest) of
     * its fact preconditions' costs. Stops once the goal's facts are settled.
     */
    private double[] factCosts(BitSet facts, int[] opLayer, double[] own, boolean max) {
        int no = task.ops.size();
        double[] fcost = new double[task.factNames.size()];
        java.util.Arrays.fill(fcost, Double.POSITIVE_INFINITY);
        int[] missing = new int[no];
        double[] acc = new double[no];
        NodeHeap heap = new NodeHeap();
        for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) {
            fcost[f] = 0;
            heap.push(0, f);
        }
        for (int o = 0; o < no; o++) {
            missing[o] = preFacts[o].length;
            if (missing[o] == 0 && (opLayer == null || opLayer[o] >= 0)) relax(o, own[o], fcost, heap);
        }
        int targets = goalFacts.length;
        boolean[] settled = new boolean[fcost.length];
        while (!heap.isEmpty() && targets > 0) {
            long key = heap.topKey();
            int f = heap.pop();
            if (settled[f] || Double.longBitsToDouble(key) > fcost[f]) continue;
            settled[f] = true;
            if (isGoalFact[f]) targets--;
            for (int o : factOps[f]) {
                acc[o] = max ? Math.max(acc[o], fcost[f]) : acc[o] + fcost[f];
                if (--missing[o] == 0 && (opLayer == null || opLayer[o] >= 0)) relax(o, own[o] + acc[o], fcost, heap);
            }
        }
        return fcost;
    }

    private void relax(int o, double c, double[] fcost, NodeHeap heap) {
        for (NumericTask.Effects e : task.ops.get(o).effects()) {
            for (int a : e.adds()) {
                if (c < fcost[a]) {
                    fcost[a] = c;
                    heap.push(Double.doubleToLongBits(c), a);
                }
            }
        }
    }

    /**
     * The earlier cost estimate, kept for tasks with disjunctive or conditional conditions: the same
     * costs, computed by relaxing every operator in every layer.
     */
    double estimateCostByLayers(BitSet facts, double[] values) {
        int nf = task.factNames.size();
        double[] fcost = new double[nf];
        java.util.Arrays.fill(fcost, Double.POSITIVE_INFINITY);
        for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) fcost[f] = 0;
        int[] opLayer = new int[task.ops.size()];
        java.util.Arrays.fill(opLayer, -1);
        int[] goalLayer = new int[goals.size()];
        java.util.Arrays.fill(goalLayer, -1);
        BitSet reached = (BitSet) facts.clone();
        double[] lo = values.clone();
        double[] hi = values.clone();
        int open = goals.size();
        int allReachedAt = -1;
        for (int layer = 0; layer <= MAX_LAYERS; layer++) {
            for (int g = 0; g < goals.size(); g++) {
                if (goalLayer[g] < 0 && holds(goals.get(g), reached, lo, hi)) {
                    goalLayer[g] = layer;
                    open--;
                }
            }
            if (open == 0 && allReachedAt < 0) allReachedAt = layer;
            BitSet nextFacts = (BitSet) reached.clone();
            double[] nextLo = lo.clone();
            double[] nextHi = hi.clone();
            boolean costChanged = false;
            for (int o = 0; o < task.ops.size(); o++) {
                NumericTask.Op op = task.ops.get(o);
                if (opLayer[o] < 0) {
                    if (!holds(op.pre(), reached, lo, hi)) continue;
                    opLayer[o] = layer; // applicable from now on: the relaxation only grows
                }
                double c = opCost[o] + factCost(op.pre(), fcost) + (numericHolds(op.pre(), values) ? 0 : cheapest * Math.max(1, opLayer[o]));
                for (NumericTask.Effects e : op.effects()) {
                    if (!holds(e.when(), reached, lo, hi)) continue;
                    double ce = e.when() == NumericTask.TRUE ? c : c + factCost(e.when(), fcost);
                    for (int f : e.adds()) {
                        nextFacts.set(f);
                        if (ce < fcost[f]) {
                            fcost[f] = ce;
                            costChanged = true;
                        }
                    }
                    if (allReachedAt < 0) for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) widen(n, lo, hi, nextLo, nextHi);
                }
            }
            if (allReachedAt >= 0 && (!costChanged || layer > allReachedAt + 8)) {
                double sum = 0;
                for (int g = 0; g < goals.size(); g++) {
                    NumericTask.Cond c = goals.get(g);
                    sum += factCost(c, fcost) + (numericHolds(c, values) ? 0 : cheapest * Math.max(1, goalLayer[g]));
                }
                return sum;
            }
            boolean changed = costChanged || !nextFacts.equals(reached);
            for (int i = 0; i < lo.length && !changed; i++) changed = matters(i, lo, hi, nextLo, nextHi);
            if (!changed) return Double.POSITIVE_INFINITY;
            reached = nextFacts;
            lo = nextLo;
            hi = nextHi;
        }
        return Double.POSITIVE_INFINITY;
    }

    /** The summed cost of a condition's facts (the cheapest part of a disjunction). */
    private static double factCost(NumericTask.Cond c, double[] fcost) {
        if (c instanceof NumericTask.Fact f) return f.positive() ? fcost[f.id()] : 0;
        if (c instanceof NumericTask.All a) {
            double s = 0;
            for (NumericTask.Cond p : a.parts()) s += factCost(p, fcost);
            return s;
        }
        if (c instanceof NumericTask.Any a) {
            double m = Double.POSITIVE_INFINITY;
            for (NumericTask.Cond p : a.parts()) m = Math.min(m, factCost(p, fcost));
            return m == Double.POSITIVE_INFINITY ? 0 : m;
        }
        return 0;
    }

    /** Whether the condition's comparisons hold in the state's values (its facts not considered). */
    private static boolean numericHolds(NumericTask.Cond c, double[] values) {
        if (c instanceof NumericTask.Cmp m) {
            return NumericTask.holds(m.op(), NumericTask.value(m.left(), values), NumericTask.value(m.right(), values));
        }
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!numericHolds(p, values)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (numericHolds(p, values)) return true;
            return a.parts().isEmpty();
        }
        return true;
    }

    /**
     * The layer estimate computed as Metric-FF's graph is defined, every operator visited in every layer:
     * the reference {@link #estimate} is checked against ({@code NumericHeuristicTest}); quadratic, so not
     * used by the search.
     */
    int estimateByLayers(BitSet facts, double[] values) {
        BitSet reached = (BitSet) facts.clone();
        double[] lo = values.clone();
        double[] hi = values.clone();
        boolean[] done = new boolean[goals.size()];
        boolean[] fired = new boolean[pure.length];
        int open = goals.size();
        int sum = 0;
        boolean checkedOptimistically = false;
        for (int layer = 0; layer <= MAX_LAYERS; layer++) {
            for (int g = 0; g < goals.size(); g++) {
                if (!done[g] && holds(goals.get(g), reached, lo, hi)) {
                    done[g] = true;
                    open--;
                    sum += layer;
                }
            }
            if (open == 0) return sum;
            BitSet nextFacts = (BitSet) reached.clone();
            double[] nextLo = lo.clone();
            double[] nextHi = hi.clone();
            for (int o = 0; o < pure.length; o++) {
                // the relaxation only grows: an operator applicable once stays so, and one that only adds
                // facts has nothing more to give after its first layer
                if (!fired[o]) {
                    if (!holds(task.ops.get(o).pre(), reached, lo, hi)) continue;
                    fired[o] = true;
                } else if (pure[o]) {
                    continue;
                }
                for (NumericTask.Effects e : task.ops.get(o).effects()) {
                    if (!holds(e.when(), reached, lo, hi)) continue;
                    for (int f : e.adds()) nextFacts.set(f);
                    for (NumericTask.NumEffect n : e.numeric()) if (!task.accumulator[n.fluent()]) widen(n, lo, hi, nextLo, nextHi);
                }
            }
            boolean factsChanged = !nextFacts.equals(reached);
            boolean changed = factsChanged;
            for (int i = 0; i < lo.length && !changed; i++) changed = matters(i, lo, hi, nextLo, nextHi);
            if (!changed) return DEAD_END;
            if (!factsChanged && !checkedOptimistically) {
                // only numbers still grow, perhaps forever: a goal that needs a fact no action can add is out of reach
                checkedOptimistically = true;
                if (!optimisticallyReachable(reached, done)) return DEAD_END;
            }
            reached = nextFacts;
            lo = nextLo;
            hi = nextHi;
        }
        return sum + open * MAX_LAYERS;
    }

    /** Whether every open goal can hold when facts are never deleted and every comparison counts as true. */
    private boolean optimisticallyReachable(BitSet from, boolean[] done) {
        BitSet facts = optimisticClosure(from);
        for (int g = 0; g < goals.size(); g++) if (!done[g] && !optimistic(goals.get(g), facts)) return false;
        return true;
    }

    /**
     * The facts reachable from {@code from} when facts are never deleted and every comparison counts as
     * true; cached by {@code from} (a fixpoint over all operators, asked again by many states whose graphs
     * stall on the same facts: a sixth of IPC sugar's time before).
     */
    private BitSet optimisticClosure(BitSet from) {
        BitSet known = closures.get(from);
        if (known != null) return known;
        BitSet facts = (BitSet) from.clone();
        boolean grew = true;
        while (grew) {
            grew = false;
            for (NumericTask.Op op : task.ops) {
                if (!optimistic(op.pre(), facts)) continue;
                for (NumericTask.Effects e : op.effects()) {
                    if (!optimistic(e.when(), facts)) continue;
                    for (int f : e.adds()) {
                        if (!facts.get(f)) {
                            facts.set(f);
                            grew = true;
                        }
                    }
                }
            }
        }
        if (closures.size() < CACHED_CLOSURES) closures.put((BitSet) from.clone(), facts);
        return facts;
    }

    private final java.util.Map<BitSet, BitSet> closures = new java.util.HashMap<>();
    private static final int CACHED_CLOSURES = 20_000;

    private static boolean optimistic(NumericTask.Cond c, BitSet facts) {
        if (c instanceof NumericTask.Fact f) return !f.positive() || facts.get(f.id());
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!optimistic(p, facts)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (optimistic(p, facts)) return true;
            return false;
        }
        return !(c instanceof NumericTask.Const k) || k.value();
    }

    private static void widen(NumericTask.NumEffect n, double[] lo, double[] hi, double[] nextLo, double[] nextHi) {
        int f = n.fluent();
        // the kind by its characters (increase, decrease, assign, scale-up, scale-down), not by string
        // switches: this runs for every widening effect in every layer of every state's graph
        String kind = n.kind();
        char k0 = kind.charAt(0);
        if (n.value() instanceof NumericTask.Num k && k0 != 'a' && !Double.isNaN(lo[f])) {
            // the common case (a constant step: distance tables fold to constants) without allocations
            double x = k.value();
            double a = lo[f], b = hi[f];
            if (k0 == 'i') {
                a += x;
                b += x;
            } else if (k0 == 'd') {
                a -= x;
                b -= x;
            } else {
                double[] c = kind.charAt(6) == 'u' ? product(new double[] { a, b }, new double[] { x, x })
                        : quotient(new double[] { a, b }, new double[] { x, x });
                a = c[0];
                b = c[1];
            }
            nextLo[f] = Double.isNaN(nextLo[f]) ? a : Math.min(nextLo[f], a);
            nextHi[f] = Double.isNaN(nextHi[f]) ? b : Math.max(nextHi[f], b);
            return;
        }
        if (k0 != 's') {
            // an added, subtracted or assigned expression, its bounds without arrays; an undefined or not a
            // number bound takes the general way below, which does what it always did
            double vl = low(n.value(), lo, hi);
            double vh = high(n.value(), lo, hi);
            if (!Double.isNaN(vl) && !Double.isNaN(vh)) {
                double a;
                double b;
                if (k0 == 'a') {
                    a = vl;
                    b = vh;
                } else {
                    if (Double.isNaN(lo[f])) return;
                    a = k0 == 'i' ? lo[f] + vl : lo[f] - vh;
                    b = k0 == 'i' ? hi[f] + vh : hi[f] - vl;
                }
                nextLo[f] = Double.isNaN(nextLo[f]) ? a : Math.min(nextLo[f], a);
                nextHi[f] = Double.isNaN(nextHi[f]) ? b : Math.max(nextHi[f], b);
                return;
            }
        }
        double[] v = interval(n.value(), lo, hi);
        if (v == null) v = interval(n.value(), lo, hi);
        if (v == null) return;
        double a;
        double b;
        if (n.kind().equals("assign")) {
            a = v[0];
            b = v[1];
        } else {
            if (Double.isNaN(lo[f])) return;
            double[] c = switch (n.kind()) {
                case "increase" -> new double[] { lo[f] + v[0], hi[f] + v[1] };
                case "decrease" -> new double[] { lo[f] - v[1], hi[f] - v[0] };
                case "scale-up" -> product(new double[] { lo[f], hi[f] }, v);
                default -> quotient(new double[] { lo[f], hi[f] }, v);
            };
            if (c == null) return;
            a = c[0];
            b = c[1];
        }
        nextLo[f] = Double.isNaN(nextLo[f]) ? a : Math.min(nextLo[f], a);
        nextHi[f] = Double.isNaN(nextHi[f]) ? b : Math.max(nextHi[f], b);
    }

    static boolean holds(NumericTask.Cond c, BitSet facts, double[] lo, double[] hi) {
        if (c instanceof NumericTask.Fact f) return !f.positive() || facts.get(f.id());
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!holds(p, facts, lo, hi)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (holds(p, facts, lo, hi)) return true;
            return false;
        }
        if (c instanceof NumericTask.Const k) return k.value();
        NumericTask.Cmp m = (NumericTask.Cmp) c;
        // the bounds one at a time, without arrays: this runs for every open condition in every layer of
        // every state's graph (the most of a numeric search's time). An undefined fluent gives NaN, and
        // every comparison with NaN is false, as interval's null was.
        String op = m.op();
        char c0 = op.charAt(0);
        boolean strict = op.length() == 1;
        if (c0 == '<') {
            double l = low(m.left(), lo, hi);
            double r = high(m.right(), lo, hi);
            return strict ? l < r : l <= r;
        }
        if (c0 == '>') {
            double l = high(m.left(), lo, hi);
            double r = low(m.right(), lo, hi);
            return strict ? l > r : l >= r;
        }
        double ll = low(m.left(), lo, hi);
        double lh = high(m.left(), lo, hi);
        double rl = low(m.right(), lo, hi);
        double rh = high(m.right(), lo, hi);
        if (Double.isNaN(ll) || Double.isNaN(lh) || Double.isNaN(rl) || Double.isNaN(rh)) return false;
        return ll <= rh && rl <= lh;
    }

    /** The lower bound of {@link #interval}'s interval, NaN where it is null. */
    static double low(NumericTask.Expr e, double[] lo, double[] hi) {
        if (e instanceof NumericTask.Num n) return n.value();
        if (e instanceof NumericTask.Var v) return lo[v.fluent()];
        if (e instanceof NumericTask.Neg n) return -high(n.operand(), lo, hi);
        NumericTask.Bin b = (NumericTask.Bin) e;
        return switch (b.op()) {
            case '+' -> low(b.left(), lo, hi) + low(b.right(), lo, hi);
            case '-' -> low(b.left(), lo, hi) - high(b.right(), lo, hi);
            default -> bound(b, lo, hi, true);
        };
    }

    /** The upper bound of {@link #interval}'s interval, NaN where it is null. */
    static double high(NumericTask.Expr e, double[] lo, double[] hi) {
        if (e instanceof NumericTask.Num n) return n.value();
        if (e instanceof NumericTask.Var v) return Double.isNaN(lo[v.fluent()]) ? Double.NaN : hi[v.fluent()];
        if (e instanceof NumericTask.Neg n) return -low(n.operand(), lo, hi);
        NumericTask.Bin b = (NumericTask.Bin) e;
        return switch (b.op()) {
            case '+' -> high(b.left(), lo, hi) + high(b.right(), lo, hi);
            case '-' -> high(b.left(), lo, hi) - low(b.right(), lo, hi);
            default -> bound(b, lo, hi, false);
        };
    }

    /** A product's or quotient's bound: rare in conditions, so through {@link #interval}. */
    private static double bound(NumericTask.Bin b, double[] lo, double[] hi, boolean lower) {
        double[] v = interval(b, lo, hi);
        return v == null ? Double.NaN : lower ? v[0] : v[1];
    }

    /** The interval of an expression, or null while a fluent it reads has no value yet. */
    static double[] interval(NumericTask.Expr e, double[] lo, double[] hi) {
        if (e instanceof NumericTask.Num n) return new double[] { n.value(), n.value() };
        if (e instanceof NumericTask.Var v) return Double.isNaN(lo[v.fluent()]) ? null : new double[] { lo[v.fluent()], hi[v.fluent()] };
        if (e instanceof NumericTask.Neg n) {
            double[] x = interval(n.operand(), lo, hi);
            return x == null ? null : new double[] { -x[1], -x[0] };
        }
        NumericTask.Bin b = (NumericTask.Bin) e;
        double[] x = interval(b.left(), lo, hi);
        double[] y = interval(b.right(), lo, hi);
        if (x == null || y == null) return null;
        return switch (b.op()) {
            case '+' -> new double[] { x[0] + y[0], x[1] + y[1] };
            case '-' -> new double[] { x[0] - y[1], x[1] - y[0] };
            case '*' -> product(x, y);
            default -> quotient(x, y);
        };
    }

    private static double[] product(double[] x, double[] y) {
        double p1 = x[0] * y[0], p2 = x[0] * y[1], p3 = x[1] * y[0], p4 = x[1] * y[1];
        return new double[] { Math.min(Math.min(p1, p2), Math.min(p3, p4)), Math.max(Math.max(p1, p2), Math.max(p3, p4)) };
    }

    private static double[] quotient(double[] x, double[] y) {
        if (y[0] <= 0 && y[1] >= 0) return new double[] { Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY };
        return product(x, new double[] { 1 / y[1], 1 / y[0] });
    }
}
