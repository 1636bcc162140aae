package org.triad.sim;

/** Segment geometry used for line-of-sight, clearance and door-crossing tests. */
final class Segments {
    private Segments() {
    }

    static double pointDistance(Vec2 p, Vec2 a, Vec2 b) {
        Vec2 ab = b.minus(a);
        double len2 = ab.dot(ab);
        if (len2 < 1e-18) {
            return p.distance(a);
        }
        double t = Math.max(0, Math.min(1, p.minus(a).dot(ab) / len2));
        return p.distance(a.plus(ab.times(t)));
    }

    static boolean intersect(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
        double d1 = orient(q1, q2, p1);
        double d2 = orient(q1, q2, p2);
        double d3 = orient(p1, p2, q1);
        double d4 = orient(p1, p2, q2);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
            return true;
        }
        return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2))
                || (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
    }

    static double segmentDistance(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
        if (intersect(p1, p2, q1, q2)) {
            return 0;
        }
        return Math.min(Math.min(pointDistance(p1, q1, q2), pointDistance(p2, q1, q2)),
                Math.min(pointDistance(q1, p1, p2), pointDistance(q2, p1, p2)));
    }

    private static double orient(Vec2 a, Vec2 b, Vec2 c) {
        return b.minus(a).cross(c.minus(a));
    }

    private static boolean onSegment(Vec2 a, Vec2 b, Vec2 p) {
        return Math.min(a.x(), b.x()) <= p.x() && p.x() <= Math.max(a.x(), b.x())
                && Math.min(a.y(), b.y()) <= p.y() && p.y() <= Math.max(a.y(), b.y());
    }
}
