package org.triad.planner;

/**
 * The relaxed plan both FF heuristics extract once their exploration has reached the goals: backwards
 * from the goals through each fact's supporter. Its value counts each action once (a conditional
 * effect's relaxed operator counts as its action, a derived-predicate rule not at all); its
 * operators applicable in the state are the helpful actions. Scratch marks are invalidated by an
 * epoch counter, so an extraction only touches the relaxed plan.
 */
final class RelaxedPlanExtraction {
    private final RelaxedOps t;
    /** Per task operator: epoch in which it was counted in the relaxed plan / made helpful. */
    private final int[] counted;
    private final int[] helpfulMark;
    private final int[] opMark;
    private final int[] factMark;
    private final int[] stack;
    private int epoch;
    private int[] helpful = new int[16];
    private int helpfulCount;

    RelaxedPlanExtraction(SearchTask task) {
        t = task.relaxed;
        counted = new int[task.ops.length];
        helpfulMark = new int[task.ops.length];
        opMark = new int[t.count];
        factMark = new int[t.size];
        stack = new int[t.size];
    }

    /** No helpful actions (an evaluation that extracted no relaxed plan). */
    void clear() {
        helpfulCount = 0;
    }

    /**
     * @param distance per fact reached by the exploration: 0 if true in the state, positive otherwise
     * @param supporter per fact reached and not true in the state: the relaxed operator that reached it
     * @return the number of actions in the relaxed plan
     */
    int extract(int[] goals, int[] distance, int[] supporter) {
        epoch++;
        helpfulCount = 0;
        int h = 0;
        int sp = 0;
        for (int g : goals) {
            if (distance[g] > 0 && factMark[g] != epoch) {
                factMark[g] = epoch;
                stack[sp++] = g;
            }
        }
        while (sp > 0) {
            int o = supporter[stack[--sp]];
            if (opMark[o] == epoch) continue;
            opMark[o] = epoch;
            int taskOp = t.op[o];
            if (taskOp >= 0 && counted[taskOp] != epoch) {
                counted[taskOp] = epoch;
                h++;
            }
            boolean applicable = true;
            for (int p : t.pre[o]) {
                if (distance[p] > 0) {
                    applicable = false;
                    if (factMark[p] != epoch) {
                        factMark[p] = epoch;
                        stack[sp++] = p;
                    }
                }
            }
            if (applicable && taskOp >= 0 && helpfulMark[taskOp] != epoch) {
                helpfulMark[taskOp] = epoch;
                if (helpfulCount == helpful.length) helpful = java.util.Arrays.copyOf(helpful, helpfulCount * 2);
                helpful[helpfulCount++] = taskOp;
            }
        }
        return h;
    }

    int helpfulCount() {
        return helpfulCount;
    }

    int helpful(int i) {
        return helpful[i];
    }
}
