package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Removes detours from a valid plan: cycles (a state visited twice) and then greedily every
 * action whose removal, together with the later actions that become inapplicable, still reaches
 * the goal (greedy action elimination). With {@code replace}, where that fails, the removal is tried
 * once more with each later action that became inapplicable replaced by a {@linkplain Siblings
 * sibling} that is applicable: many domains name a fact's old value in an action's parameters
 * (woodworking's {@code do-plane ?x ?m ?oldsurface ?oldcolour ?oldtreatment}), so removing a
 * needless step (glazing a part that is planed again later) makes the later action's ground form
 * inapplicable although the same action with the true old value would do. The result is always a
 * valid plan: only applicable actions are applied, and the goal is checked.
 */
final class PlanShortener {
    private PlanShortener() { }

    static int[] shorten(SearchTask t, Successors s, int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        return shorten(t, s, init, goalPos, goalNeg, plan, false);
    }

    static int[] shorten(SearchTask t, Successors s, int[] init, int[] goalPos, int[] goalNeg, int[] plan, boolean replace) {
        plan = removeCycles(s, init, plan);
        Siblings siblings = replace ? new Siblings(t) : null;
        boolean changed = true;
        while (changed) {
            changed = false;
            // the state before action i is carried along (the prefix before i never changes when i
            // goes), so a pass replays each suffix once instead of the whole plan per action
            int[] before = init;
            for (int i = 0; i < plan.length; i++) {
                if (siblings != null) siblings.couldReplace = false;
                int[] candidate = eliminate(s, before, goalPos, goalNeg, plan, i, siblings, false);
                if (candidate == null && siblings != null && siblings.couldReplace) {
                    candidate = eliminate(s, before, goalPos, goalNeg, plan, i, siblings, true);
                }
                if (candidate != null) {
                    plan = candidate;
                    changed = true;
                    i--;
                    continue;
                }
                before = s.apply(before, plan[i]);
            }
        }
        return plan;
    }

    private static int[] removeCycles(Successors s, int[] init, int[] plan) {
        List<int[]> states = new ArrayList<>();
        states.add(init);
        for (int o : plan) states.add(s.apply(states.get(states.size() - 1), o));
        List<Integer> out = new ArrayList<>();
        Map<List<Integer>, Integer> last = new HashMap<>();
        for (int i = 0; i < states.size(); i++) last.put(key(states.get(i)), i);
        int i = 0;
        while (i < plan.length) {
            int j = last.get(key(states.get(i)));
            if (j > i) {
                i = j;
                continue;
            }
            out.add(plan[i]);
            i++;
        }
        return out.stream().mapToInt(Integer::intValue).toArray();
    }

    private static List<Integer> key(int[] state) {
        List<Integer> k = new ArrayList<>(state.length);
        for (int f : state) k.add(f);
        return k;
    }

    /**
     * The plan without action {@code skip} (and the later ones it enables), or null; {@code before} is
     * the state before it. With {@code replace}, a later action that became inapplicable is replaced
     * by its first applicable sibling, if any; without, it goes (and {@code siblings.couldReplace},
     * where {@code siblings} is given, tells whether one could have been replaced: only then is the
     * second try worth its replay).
     */
    private static int[] eliminate(Successors s, int[] before, int[] goalPos, int[] goalNeg, int[] plan, int skip, Siblings siblings,
                                   boolean replace) {
        int[] state = before;
        List<Integer> kept = new ArrayList<>();
        for (int i = 0; i < skip; i++) kept.add(plan[i]);
        for (int i = skip + 1; i < plan.length; i++) {
            int o = plan[i];
            if (!s.isApplicable(state, o)) {
                int sibling = -1;
                if (siblings != null) {
                    sibling = siblings.applicable(s, state, o);
                    siblings.couldReplace |= sibling >= 0;
                }
                o = replace ? sibling : -1;
            }
            if (o >= 0) {
                state = s.apply(state, o);
                kept.add(o);
            }
        }
        if (!Successors.satisfies(state, goalPos, goalNeg)) return null;
        return kept.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * Operators of one schema with the same add effects and cost and no conditional effects: they
     * differ only in what they require and delete, which in such domains is the old value of what
     * they set. Indexed on first use, for the operators a plan holds.
     */
    private static final class Siblings {
        private static final int[] NONE = new int[0];
        private final SearchTask t;
        private final Map<Integer, int[]> of = new HashMap<>();
        private Map<List<Object>, List<Integer>> byKey;
        /** Some action dropped in the last try without replacing had an applicable sibling. */
        boolean couldReplace;

        Siblings(SearchTask t) {
            this.t = t;
        }

        private List<Object> key(int o) {
            GroundOp op = t.ops[o];
            return List.of(op.name(), new IntKey(op.add()), op.cost());
        }

        /** The operators of {@code o}'s kind, ascending by id (itself included); empty if it has no siblings. */
        private int[] of(int o) {
            if (t.when[o] != null) return NONE;
            if (byKey == null) {
                byKey = new HashMap<>();
                for (int p = 0; p < t.ops.length; p++) {
                    if (t.when[p] == null) byKey.computeIfAbsent(key(p), k -> new ArrayList<>()).add(p);
                }
            }
            return of.computeIfAbsent(o, x -> {
                List<Integer> all = byKey.get(key(x));
                return all.size() < 2 ? NONE : all.stream().mapToInt(Integer::intValue).toArray();
            });
        }

        int applicable(Successors s, int[] state, int o) {
            for (int p : of(o)) if (p != o && s.isApplicable(state, p)) return p;
            return -1;
        }
    }
}
