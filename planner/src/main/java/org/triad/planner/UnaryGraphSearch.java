package org.triad.planner;

/**
 * Exact shortest plans for "graph-like" tasks: when every relevant operator has a single positive
 * precondition and no negative one, and the goal is one fact, a plan is a path in the graph whose
 * nodes are facts (an operator needs only the fact its predecessor added), so a breadth-first
 * search from the true facts finds an optimal plan in time linear in the task, e.g. a robot's
 * route to a waypoint. Unreached goal means unsolvable.
 */
final class UnaryGraphSearch {
    private UnaryGraphSearch() { }

    static boolean applies(SearchTask t, int[] goalPos, int[] goalNeg) {
        if (goalPos.length != 1 || goalNeg.length != 0 || t.noPre.length != 0 || t.hasConditionalEffects || t.axioms != null) return false;
        for (int o = 0; o < t.ops.length; o++) {
            if (t.pre[o].length != 1 || t.neg[o].length != 0) return false;
        }
        return true;
    }

    /** The operators of a shortest plan, or null if the goal is unreachable. */
    static int[] search(SearchTask t, int[] init, int goal) {
        int[] via = new int[t.numFacts];
        java.util.Arrays.fill(via, -2);
        int[] queue = new int[t.numFacts];
        int head = 0;
        int tail = 0;
        for (int f : init) {
            via[f] = -1;
            queue[tail++] = f;
        }
        while (head < tail && via[goal] == -2) {
            int f = queue[head++];
            for (int o : t.preOf[f]) {
                for (int a : t.add[o]) {
                    if (via[a] == -2) {
                        via[a] = o;
                        queue[tail++] = a;
                    }
                }
            }
        }
        if (via[goal] == -2) return null;
        int len = 0;
        for (int f = goal; via[f] >= 0; f = t.pre[via[f]][0]) len++;
        int[] plan = new int[len];
        for (int f = goal; via[f] >= 0; f = t.pre[via[f]][0]) plan[--len] = via[f];
        return plan;
    }
}
