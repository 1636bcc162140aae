package org.triad.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Exact A* for tasks made of a "token graph" and a small remainder, e.g. a robot that walks a map
 * and loads or unloads things at places.
 *
 * <p><b>Structure.</b> A <em>move</em> is an operator with exactly one positive precondition
 * {@code p}, no negative one, deleting {@code p} and adding one other fact. The move facts (graph
 * nodes) are the facts moves need or add. The structure applies when every other operator neither
 * adds nor deletes a node, needs at most one node and never a node's absence, the initial state
 * holds exactly one node (the token's position; moves keep it at exactly one), and the goal needs
 * at most one node and never a node's absence.
 *
 * <p><b>Why runs of moves can be replaced by shortest paths.</b> Moves read and write only the
 * token; other operators read it only through their single node precondition and never change it.
 * So in any plan, the moves between two other operators form a walk from the token's position to
 * the next operator's node (or can be postponed past an operator that needs no node), and
 * replacing the walk by a shortest path keeps the plan valid and makes it no longer. Hence the
 * optimal plans are found by searching over states reached right after a non-move operator, where
 * a step applies operator {@code o} at cost {@code dist(position, node(o)) + 1} and ends with the
 * token at {@code node(o)}; the last step adds the walk to the goal node.
 *
 * <p><b>Heuristic.</b> For a goal fact {@code f}, {@code R_f(v)} = 1 + the graph distance from
 * {@code v} to the nearest node of an operator adding {@code f} (1 if one needs no node), computed
 * once per search by a reverse breadth-first search; for the goal node, the distance to it.
 * {@code h = max} over unsatisfied goal facts. Any plan must walk to an achiever's node and apply it,
 * so h is admissible, and by the triangle inequality consistent: A* returns optimal plans.
 * The search is bounded in work; callers fall back to other searches when it gives up.
 */
final class CompressedGraphSearch {
    static final int INFINITE = Integer.MAX_VALUE / 4;

    /** The graph/remainder split of a task, or why there is none. */
    static final class Structure {
        final boolean valid;
        final boolean[] node;
        /** Moves leaving a node, and moves entering it. */
        final int[][] movesFrom;
        final int[][] movesInto;
        /** Per non-move operator: its node precondition, or -1; per move: -2. */
        final int[] nodeOf;
        /** Non-move operators indexed by one non-node precondition (the one with the fewest users). */
        final int[][] triggeredBy;
        /** Non-move operators with no non-node precondition. */
        final int[] untriggered;

        private Structure(SearchTask t) {
            int nf = t.numFacts;
            int no = t.ops.length;
            node = new boolean[nf];
            nodeOf = new int[no];
            boolean ok = true;
            int moves = 0;
            for (int o = 0; o < no; o++) {
                if (isMove(t, o)) {
                    nodeOf[o] = -2;
                    node[t.pre[o][0]] = true;
                    node[t.add[o][0]] = true;
                    moves++;
                }
            }
            int[] fromCount = new int[nf];
            int[] intoCount = new int[nf];
            int[] users = new int[nf];
            for (int o = 0; o < no && ok; o++) {
                if (nodeOf[o] == -2) {
                    fromCount[t.pre[o][0]]++;
                    intoCount[t.add[o][0]]++;
                    continue;
                }
                int n = -1;
                for (int p : t.pre[o]) {
                    if (!node[p]) { users[p]++; continue; }
                    if (n >= 0) ok = false;
                    n = p;
                }
                nodeOf[o] = n;
                for (int p : t.neg[o]) if (node[p]) ok = false;
                for (int p : t.add[o]) if (node[p]) ok = false;
                for (int p : t.del[o]) if (node[p]) ok = false;
            }
            valid = ok && moves > 0;
            movesFrom = new int[nf][];
            movesInto = new int[nf][];
            int[][] trig = new int[nf][];
            int[] trigCount = new int[nf];
            List<Integer> free = new ArrayList<>();
            int[] trigger = new int[no];
            if (valid) {
                for (int o = 0; o < no; o++) {
                    trigger[o] = -1;
                    if (nodeOf[o] == -2) continue;
                    for (int p : t.pre[o]) {
                        if (!node[p] && (trigger[o] < 0 || users[p] < users[trigger[o]])) trigger[o] = p;
                    }
                    if (trigger[o] < 0) free.add(o); else trigCount[trigger[o]]++;
                }
            }
            for (int f = 0; f < nf; f++) {
                movesFrom[f] = new int[fromCount[f]];
                movesInto[f] = new int[intoCount[f]];
                trig[f] = new int[trigCount[f]];
            }
            Arrays.fill(fromCount, 0);
            Arrays.fill(intoCount, 0);
            Arrays.fill(trigCount, 0);
            if (valid) {
                for (int o = 0; o < no; o++) {
                    if (nodeOf[o] == -2) {
                        int a = t.pre[o][0];
                        int b = t.add[o][0];
                        movesFrom[a][fromCount[a]++] = o;
                        movesInto[b][intoCount[b]++] = o;
                    } else if (trigger[o] >= 0) {
                        trig[trigger[o]][trigCount[trigger[o]]++] = o;
                    }
                }
            }
            triggeredBy = trig;
            untriggered = free.stream().mapToInt(Integer::intValue).toArray();
        }

        private static boolean isMove(SearchTask t, int o) {
            return t.pre[o].length == 1 && t.neg[o].length == 0 && t.add[o].length == 1 && t.del[o].length == 1
                    && t.del[o][0] == t.pre[o][0] && t.add[o][0] != t.pre[o][0];
        }
    }

    /** {@code work}: graph nodes visited plus operators tried, the quantity the work limit bounds. */
    record Result(BestFirstSearch.Outcome outcome, int[] plan, long expanded, long generated, long work) { }

    private final SearchTask t;
    private final Structure s;
    private final Successors successors;
    private final long deadline;
    private final long workLimit;
    private long work;
    private final Map<Integer, int[]> forward = new LinkedHashMap<>(16, 0.75f, true);

    CompressedGraphSearch(SearchTask t, Successors successors, long deadlineNanos, long workLimit) {
        this.t = t;
        this.s = t.graphStructure();
        this.successors = successors;
        this.deadline = deadlineNanos;
        this.workLimit = workLimit;
    }

    /** Whether the structure holds for this task, initial state and goal (see the class comment). */
    static boolean applies(SearchTask t, int[] init, int[] goalPos, int[] goalNeg) {
        // its move/remainder split reads unconditional effects only
        if (t.hasConditionalEffects || t.axioms != null) return false;
        Structure s = t.graphStructure();
        if (!s.valid) return false;
        int tokens = 0;
        for (int f : init) if (s.node[f]) tokens++;
        if (tokens != 1) return false;
        int goalNodes = 0;
        for (int g : goalPos) if (s.node[g]) goalNodes++;
        for (int g : goalNeg) if (s.node[g]) return false;
        return goalNodes <= 1;
    }

    static Structure structure(SearchTask t) {
        return new Structure(t);
    }

    /** An optimal plan, EXHAUSTED (unsolvable), or LIMIT/TIMEOUT when the bounded search gave up. */
    Result run(int[] init, int[] goalPos, int[] goalNeg) {
        int goalNode = -1;
        List<Integer> factGoals = new ArrayList<>();
        for (int g : goalPos) if (s.node[g]) goalNode = g; else factGoals.add(g);
        int[] facts = factGoals.stream().mapToInt(Integer::intValue).toArray();
        int[][] toAchiever = new int[facts.length][];
        for (int i = 0; i < facts.length; i++) toAchiever[i] = distancesToAchievers(facts[i]);
        int[] toGoalNode = goalNode >= 0 ? reverseDistances(new int[] {goalNode}, 0) : null;

        StateSpace space = new StateSpace();
        NodeHeap open = new NodeHeap();
        int h0 = h(init, position(init), facts, toAchiever, toGoalNode);
        if (h0 >= INFINITE) return new Result(BestFirstSearch.Outcome.EXHAUSTED, null, 0, 1, work);
        int root = space.add(init, -1, -1, 0, h0);
        open.push(key(h0, h0), root);
        long expanded = 0;
        long generated = 1;
        int[] mark = new int[t.numFacts];
        int epoch = 0;
        while (!open.isEmpty()) {
            if (work > workLimit) return new Result(BestFirstSearch.Outcome.LIMIT, null, expanded, generated, work);
            if (System.nanoTime() > deadline) return new Result(BestFirstSearch.Outcome.TIMEOUT, null, expanded, generated, work);
            long k = open.topKey();
            int n = open.pop();
            int[] state = space.state(n);
            int g = space.g(n);
            if (k != key(g + space.h(n), space.h(n))) continue; // stale entry
            int pos = position(state);
            if (satisfiesFacts(state, facts, goalNeg)) return new Result(BestFirstSearch.Outcome.FOUND, plan(space, n, goalNode), expanded, generated, work);
            expanded++;
            int[] dist = forward(pos);
            epoch++;
            for (int f : state) mark[f] = epoch;
            for (int o : s.untriggered) {
                generated += expand(space, open, n, state, pos, g, dist, o, mark, epoch, facts, toAchiever, toGoalNode);
            }
            for (int f : state) {
                if (s.node[f]) continue;
                for (int o : s.triggeredBy[f]) {
                    generated += expand(space, open, n, state, pos, g, dist, o, mark, epoch, facts, toAchiever, toGoalNode);
                }
            }
        }
        return new Result(BestFirstSearch.Outcome.EXHAUSTED, null, expanded, generated, work);
    }

    private int expand(StateSpace space, NodeHeap open, int parent, int[] state, int pos, int g, int[] dist, int o, int[] mark,
                       int epoch, int[] facts, int[][] toAchiever, int[] toGoalNode) {
        work++;
        for (int p : t.pre[o]) if (!s.node[p] && mark[p] != epoch) return 0;
        for (int p : t.neg[o]) if (mark[p] == epoch) return 0;
        int at = s.nodeOf[o] >= 0 ? s.nodeOf[o] : pos;
        if (dist[at] >= INFINITE) return 0;
        int[] child = successors.apply(moveToken(state, pos, at), o);
        int cg = g + dist[at] + 1;
        int existing = space.find(child);
        if (existing >= 0) {
            if (cg < space.g(existing)) {
                space.reparent(existing, parent, o, cg);
                open.push(key(cg + space.h(existing), space.h(existing)), existing);
            }
            return 0;
        }
        int ch = h(child, at, facts, toAchiever, toGoalNode);
        if (ch >= INFINITE) return 1;
        int c = space.add(child, parent, o, cg, ch);
        open.push(key(cg + ch, ch), c);
        return 1;
    }

    private static long key(long f, int h) {
        return (f << 24) | Math.min(h, (1 << 24) - 1);
    }

    /** The goal's facts other than its node (reached by the final walk, priced into f exactly). */
    private static boolean satisfiesFacts(int[] state, int[] facts, int[] goalNeg) {
        return Successors.satisfies(state, facts, goalNeg);
    }

    private int h(int[] state, int pos, int[] facts, int[][] toAchiever, int[] toGoalNode) {
        int h = toGoalNode == null ? 0 : toGoalNode[pos];
        for (int i = 0; i < facts.length; i++) {
            if (Arrays.binarySearch(state, facts[i]) >= 0) continue;
            h = Math.max(h, toAchiever[i][pos]);
        }
        return h;
    }

    private int position(int[] state) {
        for (int f : state) if (s.node[f]) return f;
        throw new IllegalStateException("no token position in state");
    }

    private static int[] moveToken(int[] state, int from, int to) {
        if (from == to) return state;
        int[] out = new int[state.length];
        int n = 0;
        boolean placed = false;
        for (int f : state) {
            if (f == from) continue;
            if (!placed && to < f) { out[n++] = to; placed = true; }
            out[n++] = f;
        }
        if (!placed) out[n++] = to;
        return out;
    }

    /** 1 + distance from each node to the nearest node of an achiever of f (1 everywhere if one needs none). */
    private int[] distancesToAchievers(int f) {
        List<Integer> sources = new ArrayList<>();
        for (int o = 0; o < t.ops.length; o++) {
            if (s.nodeOf[o] == -2 || !contains(t.add[o], f)) continue;
            if (s.nodeOf[o] < 0) {
                int[] one = new int[t.numFacts];
                Arrays.fill(one, 1);
                return one;
            }
            sources.add(s.nodeOf[o]);
        }
        return reverseDistances(sources.stream().mapToInt(Integer::intValue).toArray(), 1);
    }

    private static boolean contains(int[] xs, int x) {
        for (int y : xs) if (y == x) return true;
        return false;
    }

    private int[] reverseDistances(int[] sources, int base) {
        int[] d = new int[t.numFacts];
        Arrays.fill(d, INFINITE);
        int[] queue = new int[t.numFacts];
        int head = 0;
        int tail = 0;
        for (int v : sources) if (d[v] == INFINITE) { d[v] = base; queue[tail++] = v; }
        while (head < tail) {
            int v = queue[head++];
            for (int m : s.movesInto[v]) {
                int u = t.pre[m][0];
                if (d[u] == INFINITE) { d[u] = d[v] + 1; queue[tail++] = u; }
            }
        }
        work += tail;
        return d;
    }

    /** Distances from a node, kept for the last few positions (states often share the token's place). */
    private int[] forward(int from) {
        int[] d = forward.get(from);
        if (d != null) return d;
        d = new int[t.numFacts];
        Arrays.fill(d, INFINITE);
        int[] queue = new int[t.numFacts];
        int head = 0;
        int tail = 0;
        d[from] = 0;
        queue[tail++] = from;
        while (head < tail) {
            int v = queue[head++];
            for (int m : s.movesFrom[v]) {
                int w = t.add[m][0];
                if (d[w] == INFINITE) { d[w] = d[v] + 1; queue[tail++] = w; }
            }
        }
        work += tail;
        forward.put(from, d);
        if (forward.size() > 32) forward.remove(forward.keySet().iterator().next());
        return d;
    }

    /** The moves of a shortest walk, following decreasing distance to the target. */
    private void walk(int from, int to, List<Integer> out) {
        if (from == to) return;
        int[] d = reverseDistances(new int[] {to}, 0);
        if (d[from] >= INFINITE) throw new IllegalStateException("no walk between nodes the search connected");
        for (int v = from; v != to; ) {
            int next = -1;
            for (int m : s.movesFrom[v]) {
                if (d[t.add[m][0]] == d[v] - 1) {
                    out.add(m);
                    next = t.add[m][0];
                    break;
                }
            }
            v = next;
        }
    }

    private int[] plan(StateSpace space, int n, int goalNode) {
        List<Integer> nodes = new ArrayList<>();
        for (int x = n; x >= 0; x = space.parent(x)) nodes.add(x);
        List<Integer> out = new ArrayList<>();
        for (int i = nodes.size() - 1; i > 0; i--) {
            int parent = nodes.get(i);
            int o = space.op(nodes.get(i - 1));
            int pos = position(space.state(parent));
            walk(pos, s.nodeOf[o] >= 0 ? s.nodeOf[o] : pos, out);
            out.add(o);
        }
        if (goalNode >= 0) walk(position(space.state(n)), goalNode, out);
        return out.stream().mapToInt(Integer::intValue).toArray();
    }
}
