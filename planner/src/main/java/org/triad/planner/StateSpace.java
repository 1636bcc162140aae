package org.triad.planner;

import java.util.Arrays;

/**
 * Search nodes: the state (sorted fact ids), parent, creating operator and g, with a hash table
 * for duplicate detection. Node ids are dense ints.
 */
final class StateSpace {
    private int[][] states = new int[1024][];
    private int[] parent = new int[1024];
    private int[] op = new int[1024];
    private int[] g = new int[1024];
    private int[] h = new int[1024];
    private int size;
    private int[] table = new int[2048];
    private int mask = 2047;

    StateSpace() {
        Arrays.fill(table, -1);
    }

    int size() {
        return size;
    }

    /** The node with this state, or -1. */
    int find(int[] state) {
        int i = Arrays.hashCode(state) & mask;
        while (true) {
            int n = table[i];
            if (n < 0) return -1;
            if (Arrays.equals(states[n], state)) return n;
            i = (i + 1) & mask;
        }
    }

    int add(int[] state, int parentNode, int operator, int gValue, int hValue) {
        if (size == states.length) {
            int cap = size * 2;
            states = Arrays.copyOf(states, cap);
            parent = Arrays.copyOf(parent, cap);
            op = Arrays.copyOf(op, cap);
            g = Arrays.copyOf(g, cap);
            h = Arrays.copyOf(h, cap);
        }
        int n = size++;
        states[n] = state;
        parent[n] = parentNode;
        op[n] = operator;
        g[n] = gValue;
        h[n] = hValue;
        if (size * 2 > table.length) rehash();
        insert(n);
        return n;
    }

    private void insert(int n) {
        int i = Arrays.hashCode(states[n]) & mask;
        while (table[i] >= 0) i = (i + 1) & mask;
        table[i] = n;
    }

    private void rehash() {
        table = new int[table.length * 2];
        mask = table.length - 1;
        Arrays.fill(table, -1);
        for (int n = 0; n < size; n++) insert(n);
    }

    int[] state(int n) { return states[n]; }
    int parent(int n) { return parent[n]; }
    int op(int n) { return op[n]; }
    int g(int n) { return g[n]; }
    int h(int n) { return h[n]; }

    void reparent(int n, int parentNode, int operator, int gValue) {
        parent[n] = parentNode;
        op[n] = operator;
        g[n] = gValue;
    }

    /** Operators from the root to the node. */
    int[] path(int n) {
        int len = 0;
        for (int x = n; parent[x] >= 0; x = parent[x]) len++;
        int[] out = new int[len];
        for (int x = n; parent[x] >= 0; x = parent[x]) out[--len] = op[x];
        return out;
    }
}
