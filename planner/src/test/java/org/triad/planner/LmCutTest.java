package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * LM-cut on a small delivery (facts: 0 at the lobby, 1 at the store, 2 at the ward, 3 holding the
 * parcel, 4 the parcel delivered): it counts the way to the store and the way on, where h^max sees only
 * the longer of the two; it is infinite where the goal is out of reach and 0 where it holds.
 */
class LmCutTest {
    private static final int[][] PRE = { { 0 }, { 1 }, { 1 }, { 2 }, { 0 }, { 1 }, { 2, 3 } };
    private static final int[][] ADD = { { 1 }, { 0 }, { 2 }, { 1 }, { 2 }, { 3 }, { 4 } };
    // lobby->store 5, store->lobby 5, store->ward 6, ward->store 6, lobby->ward 20, pick 1, drop 1
    private static final long[] COST = { 5, 5, 6, 6, 20, 1, 1 };

    @Test
    void aDeliveryCountsBothLegs() {
        LmCut lm = new LmCut(5, PRE, ADD, COST);
        // h^max: the ward 11 (through the store), holding 6, so 12; the cheapest plan costs 5 + 1 + 6 + 1
        assertEquals(13, lm.value(new int[] { 0 }, new int[] { 4 }));
        // the same object again (its scratch arrays reused) from the store
        assertEquals(8, lm.value(new int[] { 1 }, new int[] { 4 }));
        assertEquals(0, lm.value(new int[] { 2, 4 }, new int[] { 4 }));
    }

    /**
     * A work limit ends the rounds early: the cuts so far are still a lower bound (here h^max's round
     * alone, before the second landmark), {@link LmCut#stopped} says the bound is the weaker one, and the
     * next call without a limit is whole again.
     */
    @Test
    void aWorkLimitStopsAtALowerBound() {
        LmCut lm = new LmCut(5, PRE, ADD, COST);
        long h = lm.value(new int[] { 0 }, new int[] { 4 }, lm.work());
        assertTrue(lm.stopped());
        assertTrue(h >= 0 && h < 13, "h " + h);
        assertEquals(13, lm.value(new int[] { 0 }, new int[] { 4 }, Long.MAX_VALUE));
        assertTrue(!lm.stopped());
    }

    /**
     * An operator costlier than the goal's h^max can still be the way in: two goals at 10 each
     * separately, or both at once through x (11, then free). A cut that leaves out the operator from x
     * (h^max stopped at the goal's value) is no landmark, and the sum was 20; every cut must see it: 11.
     */
    @Test
    void anOperatorBeyondTheGoalsValueIsInTheCut() {
        int[][] pre = { { 0 }, { 0 }, { 0 }, { 3 } };
        int[][] add = { { 1 }, { 2 }, { 3 }, { 1, 2 } };
        long[] cost = { 10, 10, 11, 0 };
        assertEquals(11, new LmCut(4, pre, add, cost).value(new int[] { 0 }, new int[] { 1, 2 }));
    }

    @Test
    void anUnreachableGoalIsInfinite() {
        int[][] add = ADD.clone();
        add[5] = new int[0]; // nothing picks the parcel up
        assertEquals(LmCut.INFINITE, new LmCut(5, PRE, add, COST).value(new int[] { 0 }, new int[] { 4 }));
    }

    @Test
    void costsAreScaledToExactIntegers() {
        // 13.6 m as one corridor and as two halves compare equal after scaling
        assertEquals(LmCut.scaled(13.6), LmCut.scaled(6.8) + LmCut.scaled(6.8));
        assertEquals(LmCut.scaled(8) + LmCut.scaled(5.6), LmCut.scaled(13.6));
        assertEquals(0, LmCut.scaled(Double.NaN));
    }

    /**
     * On random small tasks (seeded) LM-cut lies between h^max and h^+ (the cheapest relaxed plan, by
     * Dijkstra over sets of facts): admissible, and at least as informed as h^max, whatever the rounds'
     * incremental updates did.
     */
    @Test
    void betweenHmaxAndTheOptimalRelaxedPlan() {
        Random random = new Random(22);
        int facts = 7;
        for (int task = 0; task < 300; task++) {
            int ops = 4 + random.nextInt(10);
            int[][] pre = new int[ops][];
            int[][] add = new int[ops][];
            long[] cost = new long[ops];
            for (int o = 0; o < ops; o++) {
                pre[o] = someFacts(random, facts, random.nextInt(3));
                add[o] = someFacts(random, facts, 1 + random.nextInt(2));
                cost[o] = random.nextInt(4) == 0 ? 0 : 1 + random.nextInt(9);
            }
            int[] state = someFacts(random, facts, 1 + random.nextInt(2));
            int[] goals = someFacts(random, facts, 1 + random.nextInt(3));
            LmCut lm = new LmCut(facts, pre, add, cost);
            long h = lm.value(state, goals);
            long plus = hPlus(facts, pre, add, cost, state, goals);
            long max = hMax(facts, pre, add, cost, state, goals);
            String what = "task " + task + ": " + Arrays.deepToString(pre) + " -> " + Arrays.deepToString(add) + " " + Arrays.toString(cost);
            if (plus >= LmCut.INFINITE) {
                assertEquals(LmCut.INFINITE, h, what);
            } else {
                assertTrue(max <= h && h <= plus, what + ": h^max " + max + " LM-cut " + h + " h^+ " + plus);
            }
            assertEquals(h, lm.value(state, goals), what); // the same object again gives the same
        }
    }

    private static int[] someFacts(Random random, int facts, int n) {
        return random.ints(0, facts).distinct().limit(n).sorted().toArray();
    }

    private static int mask(int[] fs) {
        int m = 0;
        for (int f : fs) m |= 1 << f;
        return m;
    }

    private static long hPlus(int facts, int[][] pre, int[][] add, long[] cost, int[] state, int[] goals) {
        long[] dist = new long[1 << facts];
        Arrays.fill(dist, LmCut.INFINITE);
        boolean[] done = new boolean[dist.length];
        dist[mask(state)] = 0;
        int goal = mask(goals);
        while (true) {
            int s = -1;
            for (int x = 0; x < dist.length; x++) if (!done[x] && dist[x] < LmCut.INFINITE && (s < 0 || dist[x] < dist[s])) s = x;
            if (s < 0) return LmCut.INFINITE;
            if ((s & goal) == goal) return dist[s];
            done[s] = true;
            for (int o = 0; o < pre.length; o++) {
                int p = mask(pre[o]);
                if ((s & p) != p) continue;
                int next = s | mask(add[o]);
                dist[next] = Math.min(dist[next], dist[s] + cost[o]);
            }
        }
    }

    private static long hMax(int facts, int[][] pre, int[][] add, long[] cost, int[] state, int[] goals) {
        long[] v = new long[facts];
        Arrays.fill(v, LmCut.INFINITE);
        for (int f : state) v[f] = 0;
        for (boolean changed = true; changed;) {
            changed = false;
            for (int o = 0; o < pre.length; o++) {
                long c = 0;
                for (int p : pre[o]) c = Math.max(c, v[p]);
                if (c >= LmCut.INFINITE) continue;
                for (int a : add[o]) {
                    if (c + cost[o] < v[a]) {
                        v[a] = c + cost[o];
                        changed = true;
                    }
                }
            }
        }
        long h = 0;
        for (int g : goals) h = Math.max(h, v[g]);
        return h;
    }
}
