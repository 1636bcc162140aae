package org.triad.planner;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;

import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/**
 * Plans PDDL 2.1 numeric tasks (level 2): greedy best-first search over states of facts and fluent
 * values, guided by {@link NumericHeuristic}, ties broken by cost so far and then by the order actions
 * were grounded in (so a task gets the same plan on every run). An instance is applicable when its
 * precondition holds and every value its effects compute is a finite number (a division by zero or an
 * overflow while searching makes the instance inapplicable in that state, as an undefined value does in
 * PDDL). The work is bounded by a number of expanded states as well as by the timeout.
 */
final class NumericSearch {
    /** States expanded before giving up, whatever the clock says. */
    static final long EXPANSION_BUDGET = 2_000_000;

    private NumericSearch() { }

    static boolean isNumeric(Domain domain, Problem problem) {
        return org.triad.planner.pddl.NumericParts.isNumeric(domain) || org.triad.planner.pddl.NumericParts.isNumeric(problem.goal());
    }

    private record Key(BitSet facts, double[] values) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.facts.equals(facts) && Arrays.equals(k.values, values);
        }

        @Override
        public int hashCode() {
            return facts.hashCode() * 31 + Arrays.hashCode(values);
        }
    }

    private record Node(Key state, int parent, int op, double g, int h, long order) { }

    static SolveResult solve(Domain domain, Problem problem, Duration timeout) {
        long start = System.nanoTime();
        long deadline = start + timeout.toNanos();
        NumericTask task;
        try {
            task = new NumericTask(domain, problem);
        } catch (PlanningInputException e) {
            return SolveResult.error(e.getMessage());
        } catch (RuntimeException e) {
            return SolveResult.error("internal error while grounding: " + e);
        }
        double groundMs = (System.nanoTime() - start) / 1e6;
        long searchStart = System.nanoTime();
        NumericHeuristic h = new NumericHeuristic(task);
        BitSet initFacts = new BitSet();
        task.initFacts.forEach(initFacts::set);
        Key init = new Key(initFacts, task.initValues);
        List<Node> nodes = new ArrayList<>();
        Map<Key, Integer> seen = new HashMap<>();
        PriorityQueue<Integer> open = new PriorityQueue<>((x, y) -> {
            Node a = nodes.get(x), b = nodes.get(y);
            if (a.h != b.h) return Integer.compare(a.h, b.h);
            if (a.g != b.g) return Double.compare(a.g, b.g);
            return Long.compare(a.order, b.order);
        });
        int h0 = h.estimate(init.facts, init.values);
        if (h0 == NumericHeuristic.DEAD_END) {
            return SolveResult.unsolvable("the goal is unreachable even when nothing is ever deleted and every fluent can take any value its actions reach",
                    stats(groundMs, searchStart, 0, 1));
        }
        nodes.add(new Node(init, -1, -1, 0, h0, 0));
        seen.put(init, 0);
        open.add(0);
        long expanded = 0;
        while (!open.isEmpty()) {
            int id = open.poll();
            Node n = nodes.get(id);
            if (holds(task.goal, n.state)) {
                List<Integer> ops = eliminateRedundant(task, init, opsTo(nodes, id));
                return SolveResult.solved(plan(task, ops), stats(groundMs, searchStart, expanded, nodes.size()));
            }
            if (++expanded > EXPANSION_BUDGET || System.nanoTime() > deadline) {
                return SolveResult.timeout(stats(groundMs, searchStart, expanded, nodes.size()));
            }
            for (int o = 0; o < task.ops.size(); o++) {
                NumericTask.Op op = task.ops.get(o);
                if (!holds(op.pre(), n.state)) continue;
                Key next = apply(op, n.state);
                if (next == null || seen.containsKey(next)) continue;
                int hv = h.estimate(next.facts, next.values);
                seen.put(next, nodes.size());
                if (hv == NumericHeuristic.DEAD_END) continue;
                nodes.add(new Node(next, id, o, n.g + op.cost(), hv, nodes.size()));
                open.add(nodes.size() - 1);
            }
        }
        return SolveResult.unsolvable("search space exhausted", stats(groundMs, searchStart, expanded, nodes.size()));
    }

    private static SolveResult.Stats stats(double groundMs, long searchStart, long expanded, long evaluated) {
        return new SolveResult.Stats(groundMs, (System.nanoTime() - searchStart) / 1e6, expanded, evaluated);
    }

    private static List<Integer> opsTo(List<Node> nodes, int id) {
        List<Integer> ops = new ArrayList<>();
        for (int i = id; nodes.get(i).parent >= 0; i = nodes.get(i).parent) ops.add(nodes.get(i).op);
        Collections.reverse(ops);
        return ops;
    }

    private static PddlPlan plan(NumericTask task, List<Integer> ops) {
        List<PddlStep> steps = new ArrayList<>();
        for (int o : ops) steps.add(new PddlStep(task.ops.get(o).name(), task.ops.get(o).args()));
        return new PddlPlan(steps);
    }

    /**
     * Greedy action elimination (Nakhost and Müller): drop one step at a time, first to last, wherever the
     * rest still applies and reaches the goal. Bounded by the square of the plan's length in step replays.
     */
    static List<Integer> eliminateRedundant(NumericTask task, Key init, List<Integer> plan) {
        List<Integer> current = new ArrayList<>(plan);
        for (int i = 0; i < current.size(); ) {
            List<Integer> candidate = new ArrayList<>(current);
            candidate.remove(i);
            if (reachesGoal(task, init, candidate)) current = candidate;
            else i++;
        }
        return current;
    }

    private static boolean reachesGoal(NumericTask task, Key init, List<Integer> ops) {
        Key s = init;
        for (int o : ops) {
            NumericTask.Op op = task.ops.get(o);
            if (!holds(op.pre(), s)) return false;
            s = apply(op, s);
            if (s == null) return false;
        }
        return holds(task.goal, s);
    }

    /** The state after {@code op}, or null when a value it computes is not a finite number. */
    private static Key apply(NumericTask.Op op, Key s) {
        BitSet facts = (BitSet) s.facts.clone();
        double[] values = s.values.clone();
        List<NumericTask.Effects> active = new ArrayList<>();
        for (NumericTask.Effects e : op.effects()) if (holds(e.when(), s)) active.add(e);
        for (NumericTask.Effects e : active) for (int f : e.dels()) facts.clear(f);
        for (NumericTask.Effects e : active) for (int f : e.adds()) facts.set(f);
        for (NumericTask.Effects e : active) {
            for (NumericTask.NumEffect n : e.numeric()) {
                double amount = value(n.value(), s.values);
                double current = s.values[n.fluent()];
                double v = switch (n.kind()) {
                    case "assign" -> amount;
                    case "increase" -> current + amount;
                    case "decrease" -> current - amount;
                    case "scale-up" -> current * amount;
                    default -> amount == 0 ? Double.NaN : current / amount;
                };
                if (!Double.isFinite(v)) return null;
                values[n.fluent()] = v == 0 ? 0 : v; // -0.0 and 0.0 are one state
            }
        }
        return new Key(facts, values);
    }

    static boolean holds(NumericTask.Cond c, Key s) {
        if (c instanceof NumericTask.Fact f) return s.facts.get(f.id()) == f.positive();
        if (c instanceof NumericTask.All a) {
            for (NumericTask.Cond p : a.parts()) if (!holds(p, s)) return false;
            return true;
        }
        if (c instanceof NumericTask.Any a) {
            for (NumericTask.Cond p : a.parts()) if (holds(p, s)) return true;
            return false;
        }
        if (c instanceof NumericTask.Const k) return k.value();
        NumericTask.Cmp m = (NumericTask.Cmp) c;
        return NumericTask.holds(m.op(), value(m.left(), s.values), value(m.right(), s.values));
    }

    /** NaN for an undefined fluent or a division by zero: every comparison with it is false. */
    private static double value(NumericTask.Expr e, double[] values) {
        if (e instanceof NumericTask.Num n) return n.value();
        if (e instanceof NumericTask.Var v) return values[v.fluent()];
        if (e instanceof NumericTask.Neg n) return -value(n.operand(), values);
        NumericTask.Bin b = (NumericTask.Bin) e;
        double l = value(b.left(), values);
        double r = value(b.right(), values);
        return switch (b.op()) {
            case '+' -> l + r;
            case '-' -> l - r;
            case '*' -> l * r;
            default -> r == 0 ? Double.NaN : l / r;
        };
    }
}
