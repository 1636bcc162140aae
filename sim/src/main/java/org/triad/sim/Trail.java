package org.triad.sim;

import java.util.ArrayList;
import java.util.List;

/** Breadcrumbs of an agent's positions, spaced ~0.2 m, so followers take the same way around corners. */
final class Trail {
    private static final double SPACING = 0.2;
    private final List<Vec2> points = new ArrayList<>();

    void record(Vec2 p) {
        if (points.isEmpty() || points.get(points.size() - 1).distance(p) >= SPACING) {
            points.add(p);
        }
    }

    int size() {
        return points.size();
    }

    Vec2 get(int i) {
        return points.get(i);
    }
}
