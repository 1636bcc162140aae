package org.triad.sim;

/**
 * An immutable 2D point or vector in metres (or metres per second for velocities).
 * The x axis points right (east) and the y axis points up (north) in the floor plan.
 */
public record Vec2(double x, double y) {

    /** The origin. */
    public static final Vec2 ZERO = new Vec2(0, 0);

    /**
     * @param x metres, finite
     * @param y metres, finite
     * @throws IllegalArgumentException if a coordinate is NaN or infinite
     */
    public Vec2 {
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("coordinates must be finite, got (" + x + ", " + y + ")");
        }
    }

    public Vec2 plus(Vec2 o) {
        return new Vec2(x + o.x, y + o.y);
    }

    public Vec2 minus(Vec2 o) {
        return new Vec2(x - o.x, y - o.y);
    }

    public Vec2 times(double k) {
        return new Vec2(x * k, y * k);
    }

    public double dot(Vec2 o) {
        return x * o.x + y * o.y;
    }

    /** z component of the 3D cross product. */
    public double cross(Vec2 o) {
        return x * o.y - y * o.x;
    }

    // sqrt rather than Math.hypot: hypot's overflow care is not needed at building scale and it is slow.
    public double length() {
        return Math.sqrt(x * x + y * y);
    }

    public double distance(Vec2 o) {
        double dx = x - o.x;
        double dy = y - o.y;
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** This vector rotated by +90 degrees (counter-clockwise). */
    public Vec2 perpendicular() {
        return new Vec2(-y, x);
    }

    /** The unit vector in this direction, or {@link #ZERO} for a (near) zero vector. */
    public Vec2 normalized() {
        double l = length();
        return l < 1e-12 ? ZERO : new Vec2(x / l, y / l);
    }

    /** This vector shortened to at most {@code max} length. */
    public Vec2 clampLength(double max) {
        double l = length();
        return l <= max || l < 1e-12 ? this : times(max / l);
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "(%.2f, %.2f)", x, y);
    }
}
