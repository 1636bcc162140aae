package org.triad.planner;

import java.util.Arrays;

/** An int array usable as a hash key (value semantics, cached hash). */
final class IntKey {
    final int[] values;
    private final int hash;

    IntKey(int[] values) {
        this.values = values;
        this.hash = Arrays.hashCode(values);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof IntKey k && k.hash == hash && Arrays.equals(k.values, values);
    }

    @Override
    public int hashCode() {
        return hash;
    }
}
