package org.triad.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Removes detours from a valid plan: cycles (a state visited twice) and then greedily every
 * action whose removal, together with the later actions that become inapplicable, still reaches
 * the goal (greedy action elimination).
 */
final class PlanShortener {
    private PlanShortener() { }

    static int[] shorten(SearchTask t, Successors s, int[] init, int[] goalPos, int[] goalNeg, int[] plan) {
        plan = removeCycles(s, init, plan);
        boolean changed = true;
        while (changed) {
            changed = false;
            // the state before action i is carried along (the prefix before i never changes when i
            // goes), so a pass replays each suffix once instead of the whole plan per action
            int[] before = init;
            for (int i = 0; i < plan.length; i++) {
                int[] candidate = eliminate(s, before, goalPos, goalNeg, plan, i);
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

    /** The plan without action {@code skip} (and the later ones it enables), or null; {@code before} is the state before it. */
    private static int[] eliminate(Successors s, int[] before, int[] goalPos, int[] goalNeg, int[] plan, int skip) {
        int[] state = before;
        List<Integer> kept = new ArrayList<>();
        for (int i = 0; i < skip; i++) kept.add(plan[i]);
        for (int i = skip + 1; i < plan.length; i++) {
            if (s.isApplicable(state, plan[i])) {
                state = s.apply(state, plan[i]);
                kept.add(plan[i]);
            }
        }
        if (!Successors.satisfies(state, goalPos, goalNeg)) return null;
        return kept.stream().mapToInt(Integer::intValue).toArray();
    }
}
