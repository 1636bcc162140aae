package org.triad.planner;

import java.util.Arrays;

/**
 * A min-heap of packed {@code (key << 32) | id} longs: 8 bytes per entry, ties broken by id (FIFO
 * for ids handed out in order). Used by the lazy search, whose queues hold one entry per generated
 * successor.
 */
final class LongHeap {
    private long[] items = new long[1024];
    private int size;

    boolean isEmpty() {
        return size == 0;
    }

    void push(int key, int id) {
        long x = ((long) key << 32) | (id & 0xffffffffL);
        if (size == items.length) items = Arrays.copyOf(items, size + (size >> 1));
        int i = size++;
        while (i > 0) {
            int p = (i - 1) >>> 1;
            if (items[p] <= x) break;
            items[i] = items[p];
            i = p;
        }
        items[i] = x;
    }

    /** Removes the minimum and returns its id. */
    int pop() {
        long top = items[0];
        long x = items[--size];
        int i = 0;
        while (true) {
            int c = 2 * i + 1;
            if (c >= size) break;
            if (c + 1 < size && items[c + 1] < items[c]) c++;
            if (items[c] >= x) break;
            items[i] = items[c];
            i = c;
        }
        items[i] = x;
        return (int) top;
    }
}
