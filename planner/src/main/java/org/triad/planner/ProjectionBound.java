package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;

/**
 * An admissible bound that adds a delivery's legs, where h_max over the facts sees only the longer:
 * the cheapest way to a goal fact in the task projected on two exactly-one groups of facts, the goal
 * fact's own (an item's place: at one waypoint or carried) and the group the changes of that one
 * depend on (the robot's place), found by Dijkstra over their pairs of values. A state's bound is
 * then the way to the item, the pick, the way on and the drop; for a goal on the robot's place the
 * projection is that group alone (the way through the move graph).
 * <p>
 * <b>Why it is admissible.</b> A group is exactly-one when the initial state has one of its facts and
 * every instance that adds one of them needs one of them and deletes it (unconditionally, one added),
 * and every instance that deletes one adds one; then every reachable state has exactly one. Projected
 * on such groups, an instance needs at most its group preconditions and sets at most its group effects;
 * every other condition (facts outside the groups, comparisons: the battery) is dropped, so every plan
 * maps to a path of the projection of no larger cost (costs are each instance's metric growth, at least
 * 0), and the cheapest path is a lower bound. Groups are found by closing a goal fact under "what its
 * adders need and delete" and checked as above; a task where the check fails gets no bound from here
 * (0). Not thread-safe (scratch arrays), like {@link NumericHeuristic} that owns it.
 */
final class ProjectionBound {
    /** Pairs of values beyond which the other group is left out of a projection (its table would be large). */
    private static final long MAX_PAIRS = 50_000_000;
    /** Charge levels at most, and at least (fewer: no charge dimension), and nodes at most of a charged projection. */
    private static final int MAX_LEVELS = 256;
    private static final int MIN_LEVELS = 16;
    private static final long MAX_CHARGED_NODES = 2_000_000;
    /** Nodes up to which a charged projection is made at once; above, after this many lookups that could use it. */
    private static final long EAGER_CHARGED_NODES = 20_000;
    private static final int CHARGED_AFTER_LOOKUPS = 500;
    /** Pairs up to which every value of the goal's group is kept apart (above, most are merged). */
    private static final long MAX_EXACT_PAIRS = 100_000;

    private final NumericTask task;
    private final int[][] preFacts;
    /** Per goal fact (in goal order): its projection, or null when none applies. */
    private final List<Projection> projections = new ArrayList<>();
    private final List<Integer> goalFacts = new ArrayList<>();

    /**
     * @param preFacts per instance, its positive fact preconditions (sorted), as {@link NumericHeuristic} has them
     */
    ProjectionBound(NumericTask task, int[][] preFacts, List<NumericTask.Cond> goals) {
        this.task = task;
        this.preFacts = preFacts;
        int nf = task.factNames.size();
        int[][] adders = byFact(nf, true);
        for (NumericTask.Cond c : goals) {
            if (!(c instanceof NumericTask.Fact f) || !f.positive()) continue;
            int[] own = group(f.id(), adders, nf);
            if (own == null) continue;
            // the group the own group's changes depend on most: needed by the most instances that change it
            // (the robot's place, needed by every pick and drop), then the larger, then the first found
            boolean[] inOwn = mark(own, nf);
            List<int[]> candidates = new ArrayList<>();
            List<Integer> uses = new ArrayList<>();
            for (int o = 0; o < task.ops.size(); o++) {
                if (!adds(o, inOwn)) continue;
                for (int p : preFacts[o]) {
                    if (inOwn[p]) continue;
                    int[] g = group(p, adders, nf);
                    if (g == null || overlaps(g, inOwn)) continue;
                    int k = candidates.indexOf(g);
                    if (k < 0) {
                        candidates.add(g);
                        uses.add(1);
                    } else uses.set(k, uses.get(k) + 1);
                }
            }
            int[] other = null;
            int best = 0;
            for (int k = 0; k < candidates.size(); k++) {
                int[] g = candidates.get(k);
                if (uses.get(k) > best || uses.get(k) == best && g.length > other.length) {
                    other = g;
                    best = uses.get(k);
                }
            }
            if (other != null && (long) own.length * other.length > MAX_PAIRS) other = null;
            projections.add(new Projection(f.id(), own, other, nf));
            goalFacts.add(f.id());
        }
        covers = !goals.isEmpty() && projections.size() == goals.size();
        resource = projections.isEmpty() ? null : Resource.find(task);
    }

    /**
     * Whether every goal conjunct is a fact with a projection: {@link #bound} then stands alone (h_max
     * over the facts adds little to it and costs a pass over every instance per state).
     */
    boolean coversGoal() {
        return covers;
    }

    private final boolean covers;
    /** The charge the projections account for, or null. */
    private final Resource resource;

    /**
     * A fluent spent like a battery: every instance that changes it either decreases it by a constant
     * {@code a > 0} and needs it at least {@code a} first (a top-level {@code >=} against a constant; so it
     * never falls below 0), or is a refill (any other change: a recharge). Without a refill a plan then
     * spends at most the charge it starts with, and after its last refill at most the {@code ceiling}.
     */
    record Resource(int fluent, double[] drain, boolean[] refill, double ceiling) {
        /** The most a refill leaves: the largest constant one assigns; infinite when one does anything else. */
        private static double ceiling(NumericTask task, int v, boolean[] refill) {
            double c = Double.NEGATIVE_INFINITY;
            for (int o = 0; o < refill.length; o++) {
                if (!refill[o]) continue;
                for (NumericTask.Effects e : task.ops.get(o).effects()) {
                    for (NumericTask.NumEffect n : e.numeric()) {
                        if (n.fluent() != v) continue;
                        if (!n.kind().equals("assign") || !(n.value() instanceof NumericTask.Num k)) return Double.POSITIVE_INFINITY;
                        c = Math.max(c, k.value());
                    }
                }
            }
            return c;
        }

        static Resource find(NumericTask task) {
            int no = task.ops.size();
            for (int v = 0; v < task.fluentNames.size(); v++) {
                if (task.accumulator[v]) continue;
                double[] drain = new double[no];
                boolean[] refill = new boolean[no];
                boolean ok = true;
                boolean consumed = false;
                for (int o = 0; o < no && ok; o++) {
                    NumericTask.Op op = task.ops.get(o);
                    for (NumericTask.Effects e : op.effects()) {
                        for (NumericTask.NumEffect n : e.numeric()) {
                            if (n.fluent() != v) continue;
                            double a = !(n.value() instanceof NumericTask.Num k) ? Double.NaN
                                    : n.kind().equals("decrease") ? k.value() : n.kind().equals("increase") ? -k.value() : Double.NaN;
                            if (a > 0 && e.when() == NumericTask.TRUE && drain[o] == 0 && needsAtLeast(op.pre(), v, a)) {
                                drain[o] = a;
                                consumed = true;
                            } else if (a > 0 || a == 0) {
                                if (a > 0) ok = false; // a conditional or unguarded drain: the charge may go below 0
                            } else refill[o] = true;
                        }
                    }
                    if (drain[o] > 0 && refill[o]) ok = false;
                }
                if (ok && consumed && Double.isFinite(task.initValues[v])) return new Resource(v, drain, refill, ceiling(task, v, refill));
            }
            return null;
        }

        private static boolean needsAtLeast(NumericTask.Cond pre, int v, double a) {
            for (NumericTask.Cond c : pre instanceof NumericTask.All all ? all.parts() : List.of(pre)) {
                if (c instanceof NumericTask.Cmp m && m.left() instanceof NumericTask.Var x && x.fluent() == v && m.right() instanceof NumericTask.Num k
                        && (m.op().equals(">=") || m.op().equals(">")) && k.value() >= a) return true;
            }
            return false;
        }
    }

    /** Whether some goal fact has a projection (else {@link #bound} is always 0). */
    boolean applies() {
        return !projections.isEmpty();
    }

    /**
     * The largest over the goal facts of the cheapest way to it in its projection from {@code facts},
     * each instance costing {@code own[o]} (at least 0); {@link Double#POSITIVE_INFINITY} when one has no way.
     * With {@code values} (else null), a charge too low for every way without a recharge makes it the
     * cheapest way through one ({@link Resource}).
     */
    double bound(BitSet facts, double[] values, double[] own) {
        double h = 0;
        for (Projection p : projections) {
            if (facts.get(p.goal)) continue;
            h = Math.max(h, p.cheapest(facts, values, own));
            if (h == Double.POSITIVE_INFINITY) break;
        }
        return h;
    }

    private int[][] byFact(int nf, boolean add) {
        int[] count = new int[nf];
        for (NumericTask.Op op : task.ops) for (NumericTask.Effects e : op.effects()) for (int a : add ? e.adds() : e.dels()) count[a]++;
        int[][] out = new int[nf][];
        for (int f = 0; f < nf; f++) out[f] = new int[count[f]];
        Arrays.fill(count, 0);
        for (int o = 0; o < task.ops.size(); o++) {
            for (NumericTask.Effects e : task.ops.get(o).effects()) {
                for (int a : add ? e.adds() : e.dels()) {
                    int[] row = out[a];
                    if (count[a] == 0 || row[count[a] - 1] != o) row[count[a]++] = o;
                }
            }
        }
        for (int f = 0; f < nf; f++) if (count[f] < out[f].length) out[f] = Arrays.copyOf(out[f], count[f]);
        return out;
    }

    private boolean sharesArgument(int a, int b) {
        List<String> x = arguments(task.factNames.get(a));
        for (String y : arguments(task.factNames.get(b))) if (x.contains(y)) return true;
        return false;
    }

    private static String predicate(String fact) {
        String inner = fact.startsWith("(") ? fact.substring(1) : fact;
        int space = inner.indexOf(' ');
        return space < 0 ? (inner.endsWith(")") ? inner.substring(0, inner.length() - 1) : inner) : inner.substring(0, space);
    }

    /** A fact's arguments from its name, {@code (item-at box wp3)}: [box, wp3]. */
    private static List<String> arguments(String fact) {
        String inner = fact.startsWith("(") && fact.endsWith(")") ? fact.substring(1, fact.length() - 1) : fact;
        String[] parts = inner.trim().split("\\s+");
        return Arrays.asList(parts).subList(Math.min(1, parts.length), parts.length);
    }

    private static boolean overlaps(int[] group, boolean[] in) {
        for (int f : group) if (in[f]) return true;
        return false;
    }

    private static boolean[] mark(int[] facts, int nf) {
        boolean[] in = new boolean[nf];
        for (int f : facts) in[f] = true;
        return in;
    }

    private boolean adds(int o, boolean[] in) {
        for (NumericTask.Effects e : task.ops.get(o).effects()) for (int a : e.adds()) if (in[a]) return true;
        return false;
    }

    /**
     * The exactly-one group of {@code seed}: closed under "the facts an adder of a member needs and
     * deletes", then checked (see the class comment); null when the check fails.
     */
    private int[] group(int seed, int[][] adders, int nf) {
        if (groups == null) groups = new int[nf][];
        if (groups[seed] == null) {
            int[] g = closeAndCheck(seed, adders, nf);
            groups[seed] = g == null ? NO_GROUP : g;
            // the same group from any of its members (one array, so candidates compare by identity)
            if (g != null) for (int m : g) groups[m] = g;
        }
        return groups[seed] == NO_GROUP ? null : groups[seed];
    }

    private static final int[] NO_GROUP = new int[0];
    /** Per seed fact tried, its group or {@link #NO_GROUP} (the constructor tries a few seeds per instance). */
    private int[][] groups;

    private int[] closeAndCheck(int seed, int[][] adders, int nf) {
        boolean[] in = new boolean[nf];
        List<Integer> members = new ArrayList<>();
        in[seed] = true;
        members.add(seed);
        java.util.Set<String> predicates = new java.util.HashSet<>();
        predicates.add(predicate(task.factNames.get(seed)));
        for (int i = 0; i < members.size(); i++) {
            int member = members.get(i);
            for (int o : adders[member]) {
                List<Integer> swapped = new ArrayList<>();
                for (NumericTask.Effects e : task.ops.get(o).effects()) {
                    for (int d : e.dels()) if (Arrays.binarySearch(preFacts[o], d) >= 0 && !swapped.contains(d)) swapped.add(d);
                }
                // a pick swaps the item's place for "carried" and also takes the empty hand: of several, the one
                // of a predicate already in the group (the item's place), else the one about the same object
                // (sharing an argument with the member), is the member's group; the check below decides
                if (swapped.size() > 1) {
                    List<Integer> same = new ArrayList<>(swapped);
                    same.removeIf(d -> !predicates.contains(predicate(task.factNames.get(d))));
                    if (same.size() == 1) swapped = same;
                    else swapped.removeIf(d -> !sharesArgument(member, d));
                }
                if (swapped.size() == 1 && !in[swapped.get(0)]) {
                    in[swapped.get(0)] = true;
                    members.add(swapped.get(0));
                    predicates.add(predicate(task.factNames.get(swapped.get(0))));
                }
            }
        }
        int initial = 0;
        for (int f : task.initFacts) if (in[f]) initial++;
        if (initial != 1) return null;
        for (int o = 0; o < task.ops.size(); o++) {
            NumericTask.Op op = task.ops.get(o);
            int added = 0;
            int deleted = -1;
            int deletes = 0;
            for (NumericTask.Effects e : op.effects()) {
                for (int a : e.adds()) {
                    if (!in[a]) continue;
                    if (e.when() != NumericTask.TRUE) return null;
                    added++;
                }
                for (int d : e.dels()) {
                    if (!in[d]) continue;
                    if (e.when() != NumericTask.TRUE) return null;
                    deletes++;
                    deleted = d;
                }
            }
            if (added == 0 && deletes == 0) continue;
            if (added != 1 || deletes != 1) return null;
            boolean needs = false;
            int needed = 0;
            for (int p : preFacts[o]) {
                if (!in[p]) continue;
                needed++;
                needs |= p == deleted;
            }
            if (!needs || needed != 1) return null;
        }
        return members.stream().mapToInt(Integer::intValue).sorted().toArray();
    }

    /**
     * One goal fact's projection, its costs to the goal computed once (per cost vector) by Dijkstra
     * backwards from the goal over all its pairs, so a state's bound is a lookup. When the pairs would be
     * many (an item's place at any of N waypoints times the robot's), the goal group's values other than
     * the goal, the initial one and those one change away from either (carried) are merged into one: a
     * coarser abstraction, still a lower bound, of 4 N pairs instead of N².
     */
    private final class Projection {
        final int goal;
        final int[] ownFacts;
        final int[] otherFacts;
        /** Per fact: its abstract value in the goal group (-1: not in it), its value in the other group (-1: not in it). */
        final int[] ownValue;
        final int[] otherValue;
        final int values;
        final int width;
        /** Reverse transitions in CSR form: into pair q come {@code from[k]} by instance {@code via[k]} for k in [start[q], start[q + 1]). */
        final int[] start;
        final int[] from;
        final int[] via;
        final int goalValue;
        /** Costs to the goal per pair, for the cost vector they were computed with (compared by identity). */
        private double[] toGoal;
        private double[] costsUsed;

        /** Whether the goal group's values are merged (see the class comment). */
        final boolean merged;
        private final int[] otherGroup;
        private final int nf;

        Projection(int goal, int[] own, int[] other, int nf) {
            this(goal, own, other, nf, false);
        }

        /** @param merge whether to merge the goal group's values however few the pairs */
        Projection(int goal, int[] own, int[] other, int nf, boolean merge) {
            this.goal = goal;
            this.otherGroup = other;
            this.nf = nf;
            this.ownFacts = own;
            this.otherFacts = other == null ? new int[0] : other;
            width = Math.max(1, otherFacts.length);
            int[] rawOwn = new int[nf];
            otherValue = new int[nf];
            Arrays.fill(rawOwn, -1);
            Arrays.fill(otherValue, -1);
            for (int i = 0; i < own.length; i++) rawOwn[own[i]] = i;
            for (int i = 0; i < otherFacts.length; i++) otherValue[otherFacts[i]] = i;
            // each instance that changes either group: (needed own, set own, needed other, set other), raw values
            List<int[]> rows = new ArrayList<>();
            for (int o = 0; o < task.ops.size(); o++) {
                int no = -1, so = -1, nx = -1, sx = -1;
                for (int p : preFacts[o]) {
                    if (rawOwn[p] >= 0) no = rawOwn[p];
                    if (otherValue[p] >= 0) nx = otherValue[p];
                }
                for (NumericTask.Effects e : task.ops.get(o).effects()) {
                    for (int a : e.adds()) {
                        if (rawOwn[a] >= 0) so = rawOwn[a];
                        if (otherValue[a] >= 0) sx = otherValue[a];
                    }
                }
                if (so < 0 && sx < 0) continue;
                rows.add(new int[] { no, so, nx, sx, o });
            }
            int[] abs = new int[own.length];
            int g = rawOwn[goal];
            merged = merge || (long) own.length * width > MAX_EXACT_PAIRS;
            if (!merged) {
                for (int i = 0; i < own.length; i++) abs[i] = i;
                values = own.length;
            } else {
                int init = -1;
                for (int f : own) if (task.initFacts.contains(f)) init = rawOwn[f];
                boolean[] kept = new boolean[own.length];
                kept[g] = true;
                if (init >= 0) kept[init] = true;
                for (int[] r : rows) {
                    if (r[1] >= 0 && r[0] == init && init >= 0) kept[r[1]] = true; // one change from the start (picked up)
                    if (r[1] == g && r[0] >= 0) kept[r[0]] = true; // one change before the goal (carried)
                }
                int k = 0;
                for (int i = 0; i < own.length; i++) if (kept[i]) abs[i] = k++;
                for (int i = 0; i < own.length; i++) if (!kept[i]) abs[i] = k; // the rest, merged
                values = k + (k < own.length ? 1 : 0);
            }
            ownValue = new int[nf];
            Arrays.fill(ownValue, -1);
            for (int i = 0; i < own.length; i++) ownValue[own[i]] = abs[i];
            goalValue = abs[g];
            // forward transitions of every pair, then reversed
            int pairs = values * width;
            List<List<int[]>> byOther = new ArrayList<>();
            for (int x = 0; x <= width; x++) byOther.add(new ArrayList<>());
            for (int[] r : rows) byOther.get(r[2] >= 0 ? r[2] : width).add(r); // index width: needs no other value
            int[] count = new int[pairs + 1];
            List<int[]> edges = new ArrayList<>(); // {from, to, op}
            for (int m = 0; m < values; m++) {
                for (int x = 0; x < width; x++) {
                    // the instances needing this other value, then those needing none (all of them without another group)
                    for (List<int[]> list : otherFacts.length == 0 ? List.of(byOther.get(width)) : List.of(byOther.get(x), byOther.get(width))) {
                        for (int[] r : list) {
                            if (r[0] >= 0 && abs[r[0]] != m) continue;
                            int nm = r[1] >= 0 ? abs[r[1]] : m;
                            int nx = r[3] >= 0 ? r[3] : x;
                            if (nm == m && nx == x) continue;
                            int q = nm * width + nx;
                            edges.add(new int[] { m * width + x, q, r[4] });
                            count[q]++;
                        }
                    }
                }
            }
            start = new int[pairs + 1];
            for (int q = 0; q < pairs; q++) start[q + 1] = start[q] + count[q];
            from = new int[edges.size()];
            via = new int[edges.size()];
            int[] fill = Arrays.copyOf(start, pairs);
            for (int[] e : edges) {
                from[fill[e[1]]] = e[0];
                via[fill[e[1]]++] = e[2];
            }
        }

        /** The state's pair, -1 when it is not a state the groups describe. */
        private int pairOf(BitSet facts) {
            int m0 = -1, x0 = otherFacts.length == 0 ? 0 : -1;
            for (int f = facts.nextSetBit(0); f >= 0; f = facts.nextSetBit(f + 1)) {
                if (f < ownValue.length && ownValue[f] >= 0) m0 = ownValue[f];
                if (f < otherValue.length && otherValue[f] >= 0) x0 = otherValue[f];
            }
            return m0 < 0 || x0 < 0 ? -1 : m0 * width + x0;
        }

        double cheapest(BitSet facts, double[] values, double[] own) {
            int p = pairOf(facts);
            if (p < 0) return 0; // no bound
            if (costsUsed != own) {
                cheapestDrain = new double[start.length - 1]; // one per pair
                toGoal = backwards(own, null, resource == null ? null : cheapestDrain);
                costsUsed = own;
                if (resource != null) {
                    // the least charge any way to the goal spends, and the cheapest way through a refill
                    leastDrain = backwards(resource.drain(), null, null);
                    viaRefill = backwards(own, refillSeeds(own), null);
                }
            }
            if (values == null || resource == null) return toGoal[p];
            double charge = values[resource.fluent()];
            // the cheapest way fits the charge: nothing is finer (the charge can only make ways dearer)
            if (charge >= cheapestDrain[p] - 1e-9) return toGoal[p];
            double h = charge < leastDrain[p] - 1e-9 ? Math.max(toGoal[p], viaRefill[p]) : toGoal[p];
            // the charge's dimension on the merged values (an item's place at N waypoints times N robot places
            // times the charge levels would be too many nodes to search per goal; merged, about 4 N)
            // a large table (and the merged projection it needs) waits until the search has met many such
            // states: a goal that the bound above already solves in a few (the hospital's evening delivery,
            // 15) paid twice its per-goal CPU for it
            if ((long) (start.length - 1) * MAX_LEVELS > EAGER_CHARGED_NODES && ++lowCharges <= CHARGED_AFTER_LOOKUPS) return h;
            if (coarse == null) coarse = merged ? this : new Projection(goal, ownFacts, otherGroup, nf, true);
            return Math.max(h, coarse.withCharge(facts, charge, own));
        }

        /** Lookups of a state whose charge is below its cheapest way's (a count, so the same on every run). */
        private int lowCharges;

        /** The cheapest way from the state's pair with this charge in the charge's dimension; 0 where it does not apply. */
        private double withCharge(BitSet facts, double charge, double[] own) {
            if (chargedFor != own) {
                charged = chargedProjection(own);
                chargedFor = own;
            }
            int p = pairOf(facts);
            return charged == null || p < 0 ? 0 : charged.cheapest(p, charge);
        }

        /** This projection with the goal group's values merged (itself when they are), made when first needed. */
        private Projection coarse;
        private double[] chargedFor;

        private double[] leastDrain;
        private double[] viaRefill;
        /** Per pair, the charge the way {@link #toGoal} found spends. */
        private double[] cheapestDrain;
        /** The charge as a third dimension (on the merged projection), made when {@link #cheapest} first uses it. */
        private ChargedProjection charged;

        /** Per pair where a refill applies (its group conditions hold there): its cost plus the way on from where it leaves. */
        private double[] refillSeeds(double[] own) {
            double[] seed = new double[values * width];
            Arrays.fill(seed, Double.POSITIVE_INFINITY);
            for (int[] r : refills()) {
                // the plan's last refill leaves at most the ceiling, which must then suffice for the rest
                if (leastDrain[r[1]] > resource.ceiling() + 1e-9) continue;
                seed[r[0]] = Math.min(seed[r[0]], own[r[2]] + toGoal[r[1]]);
            }
            return seed;
        }

        /** Every refill's transitions: {pair it applies in, pair it leaves, instance}. */
        private List<int[]> refills() {
            List<int[]> out = new ArrayList<>();
            for (int o = 0; o < task.ops.size(); o++) {
                if (!resource.refill()[o]) continue;
                int no = -1, nx = -1, so = -1, sx = -1;
                for (int f : preFacts[o]) {
                    if (ownValue[f] >= 0) no = ownValue[f];
                    if (otherValue[f] >= 0) nx = otherValue[f];
                }
                for (NumericTask.Effects e : task.ops.get(o).effects()) {
                    for (int a : e.adds()) {
                        if (a < ownValue.length && ownValue[a] >= 0) so = ownValue[a];
                        if (a < otherValue.length && otherValue[a] >= 0) sx = otherValue[a];
                    }
                }
                for (int m = 0; m < values; m++) {
                    if (no >= 0 && no != m) continue;
                    for (int x = 0; x < width; x++) {
                        if (nx >= 0 && nx != x) continue;
                        out.add(new int[] { m * width + x, (so >= 0 ? so : m) * width + (sx >= 0 ? sx : x), o });
                    }
                }
            }
            return out;
        }

        /**
         * The projection with the charge as a third dimension, or null where it does not apply (a refill
         * that does not assign a constant, or more than {@link #MAX_CHARGED_NODES} nodes even at
         * {@link #MIN_LEVELS} levels). Charge is counted in {@code unit}s: 1 when every drain, the
         * ceiling and the start are whole and at most {@link #MAX_LEVELS}, else the largest charge over
         * the levels. <b>Still a lower bound:</b> a state's charge is rounded up to a level and every drain
         * down, so the level never falls below the charge along any plan's projected path; a refill leaves
         * the larger of the level it finds and the ceiling's (an assignment of the ceiling leaves exactly
         * it; a conditional one, or one where the charge was higher, no more); its own condition (a charge
         * below capacity) is dropped. Every plan maps to a path here of no larger cost.
         */
        private ChargedProjection chargedProjection(double[] own) {
            double full = resource.ceiling();
            double most = Math.max(full, task.initValues[resource.fluent()]);
            if (!Double.isFinite(most) || !(most > 0)) return null;
            int pairs = values * width;
            long cap = Math.min(MAX_LEVELS, MAX_CHARGED_NODES / pairs);
            if (cap < MIN_LEVELS) return null;
            boolean whole = most == Math.rint(most) && full == Math.rint(full) && most < cap;
            for (int o = 0; o < task.ops.size() && whole; o++) whole = resource.drain()[o] == Math.rint(resource.drain()[o]);
            double unit = whole ? 1 : most / (cap - 1);
            int levels = (int) Math.ceil(most / unit - 1e-9) + 1;
            int fullLevel = (int) Math.ceil(full / unit - 1e-9);
            int[] drainLevels = new int[task.ops.size()];
            for (int o = 0; o < drainLevels.length; o++) drainLevels[o] = (int) Math.floor(resource.drain()[o] / unit + 1e-9);
            // refills by the pair they leave (a CSR as the transitions)
            List<int[]> refills = refills();
            int[] refillStart = new int[pairs + 1];
            for (int[] r : refills) refillStart[r[1] + 1]++;
            for (int q = 0; q < pairs; q++) refillStart[q + 1] += refillStart[q];
            int[] refillFrom = new int[refills.size()];
            int[] refillVia = new int[refills.size()];
            int[] fill = Arrays.copyOf(refillStart, pairs);
            for (int[] r : refills) {
                refillFrom[fill[r[1]]] = r[0];
                refillVia[fill[r[1]]++] = r[2];
            }
            double[] d = new double[pairs * levels];
            Arrays.fill(d, Double.POSITIVE_INFINITY);
            NodeHeap heap = new NodeHeap();
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < levels; c++) {
                    int node = (goalValue * width + x) * levels + c;
                    d[node] = 0;
                    heap.push(0, node);
                }
            }
            while (!heap.isEmpty()) {
                double cost = Double.longBitsToDouble(heap.topKey());
                int node = heap.pop();
                if (cost > d[node]) continue;
                int q = node / levels;
                int c = node % levels;
                for (int k = start[q]; k < start[q + 1]; k++) {
                    int pc = c + drainLevels[via[k]];
                    if (pc >= levels) continue;
                    relax(d, heap, from[k] * levels + pc, cost + own[via[k]]);
                }
                if (c < fullLevel) continue;
                for (int k = refillStart[q]; k < refillStart[q + 1]; k++) {
                    double nc = cost + own[refillVia[k]];
                    int base = refillFrom[k] * levels;
                    if (c > fullLevel) relax(d, heap, base + c, nc); // a charge above the ceiling's level is kept
                    else for (int pc = 0; pc <= fullLevel; pc++) relax(d, heap, base + pc, nc);
                }
            }
            return new ChargedProjection(unit, levels, d);
        }

        private static void relax(double[] d, NodeHeap heap, int node, double cost) {
            if (cost < d[node]) {
                d[node] = cost;
                heap.push(Double.doubleToLongBits(cost), node);
            }
        }

        /**
         * Dijkstra along the reversed transitions, each instance weighing {@code weight[o]}, from every pair
         * with the goal's value at 0 ({@code seeds} null) or from every pair at its seed; with
         * {@code drainAlong}, fills in per pair the charge its way found spends.
         */
        private double[] backwards(double[] weight, double[] seeds, double[] drainAlong) {
            double[] own = weight;
            int pairs = values * width;
            double[] d = new double[pairs];
            Arrays.fill(d, Double.POSITIVE_INFINITY);
            NodeHeap heap = new NodeHeap();
            if (seeds == null) {
                for (int x = 0; x < width; x++) {
                    d[goalValue * width + x] = 0;
                    heap.push(0, goalValue * width + x);
                }
            } else {
                for (int q = 0; q < pairs; q++) {
                    if (seeds[q] < Double.POSITIVE_INFINITY) {
                        d[q] = seeds[q];
                        heap.push(Double.doubleToLongBits(seeds[q]), q);
                    }
                }
            }
            while (!heap.isEmpty()) {
                double c = Double.longBitsToDouble(heap.topKey());
                int q = heap.pop();
                if (c > d[q]) continue;
                for (int k = start[q]; k < start[q + 1]; k++) {
                    double nc = c + own[via[k]];
                    int p = from[k];
                    if (nc < d[p]) {
                        d[p] = nc;
                        if (drainAlong != null) drainAlong[p] = drainAlong[q] + resource.drain()[via[k]];
                        heap.push(Double.doubleToLongBits(nc), p);
                    }
                }
            }
            return d;
        }
    }

    /** Costs to the goal per (pair, charge level): {@code toGoal[pair * levels + level]}. */
    private record ChargedProjection(double unit, int levels, double[] toGoal) {
        /** The cheapest way from this pair with this charge (rounded up to its level); 0 above the top level. */
        double cheapest(int pair, double charge) {
            int level = Math.max(0, (int) Math.ceil(charge / unit - 1e-9));
            return level >= levels ? 0 : toGoal[pair * levels + level];
        }
    }
}
