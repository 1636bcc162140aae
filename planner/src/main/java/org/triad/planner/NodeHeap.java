package org.triad.planner;

import java.util.Arrays;

/** A binary min-heap of search nodes ordered by a long key, ties broken by node id (FIFO). */
final class NodeHeap {
    private long[] keys = new long[256];
    private int[] nodes = new int[256];
    private int size;

    boolean isEmpty() {
        return size == 0;
    }

    int size() {
        return size;
    }

    long topKey() {
        return keys[0];
    }

    void push(long key, int node) {
        if (size == keys.length) {
            keys = Arrays.copyOf(keys, size * 2);
            nodes = Arrays.copyOf(nodes, size * 2);
        }
        int i = size++;
        while (i > 0) {
            int p = (i - 1) >>> 1;
            if (!less(key, node, keys[p], nodes[p])) break;
            keys[i] = keys[p];
            nodes[i] = nodes[p];
            i = p;
        }
        keys[i] = key;
        nodes[i] = node;
    }

    /** Removes the minimum; returns its node (its key was {@link #topKey()}). */
    int pop() {
        int top = nodes[0];
        size--;
        if (size > 0) {
            long k = keys[size];
            int n = nodes[size];
            int i = 0;
            while (true) {
                int c = 2 * i + 1;
                if (c >= size) break;
                if (c + 1 < size && less(keys[c + 1], nodes[c + 1], keys[c], nodes[c])) c++;
                if (!less(keys[c], nodes[c], k, n)) break;
                keys[i] = keys[c];
                nodes[i] = nodes[c];
                i = c;
            }
            keys[i] = k;
            nodes[i] = n;
        }
        return top;
    }

    private static boolean less(long k1, int n1, long k2, int n2) {
        return k1 < k2 || (k1 == k2 && n1 < n2);
    }
}
