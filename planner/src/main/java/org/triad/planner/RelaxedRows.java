package org.triad.planner;

/**
 * The relaxed operators of {@link RelaxedOps} as flat rows, the layout the heuristics' inner loops
 * walk: the operators having fact f as a precondition are {@code preOps[preStart[f] .. preStart[f+1])},
 * the facts operator o adds are {@code addFacts[addStart[o] .. addStart[o+1])}, and
 * {@code preCount[o]} is the number of its preconditions.
 */
final class RelaxedRows {
    final int[] preStart;
    final int[] preOps;
    final int[] preCount;
    final int[] addStart;
    final int[] addFacts;

    RelaxedRows(RelaxedOps t) {
        int nf = t.size;
        int no = t.count;
        preStart = new int[nf + 1];
        int total = 0;
        for (int f = 0; f < nf; f++) {
            preStart[f] = total;
            total += t.preOf[f].length;
        }
        preStart[nf] = total;
        preOps = new int[total];
        for (int f = 0; f < nf; f++) System.arraycopy(t.preOf[f], 0, preOps, preStart[f], t.preOf[f].length);
        preCount = new int[no];
        addStart = new int[no + 1];
        int adds = 0;
        for (int o = 0; o < no; o++) {
            preCount[o] = t.pre[o].length;
            addStart[o] = adds;
            adds += t.add[o].length;
        }
        addStart[no] = adds;
        addFacts = new int[adds];
        for (int o = 0; o < no; o++) System.arraycopy(t.add[o], 0, addFacts, addStart[o], t.add[o].length);
    }
}
