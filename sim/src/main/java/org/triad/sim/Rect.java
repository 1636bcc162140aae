package org.triad.sim;

/** An axis-aligned rectangle in metres, {@code minX < maxX} and {@code minY < maxY}. */
public record Rect(double minX, double minY, double maxX, double maxY) {

    /** @throws IllegalArgumentException if a bound is not finite or the rectangle is empty */
    public Rect {
        Checks.finite("minX", minX);
        Checks.finite("minY", minY);
        Checks.finite("maxX", maxX);
        Checks.finite("maxY", maxY);
        if (!(minX < maxX) || !(minY < maxY)) {
            throw new IllegalArgumentException("rectangle must have minX < maxX and minY < maxY, got ["
                    + minX + ", " + minY + ", " + maxX + ", " + maxY + "]");
        }
    }

    public double width() {
        return maxX - minX;
    }

    public double height() {
        return maxY - minY;
    }

    public Vec2 center() {
        return new Vec2((minX + maxX) / 2, (minY + maxY) / 2);
    }

    /** Whether {@code p} lies inside or on the border. */
    public boolean contains(Vec2 p) {
        return p.x() >= minX && p.x() <= maxX && p.y() >= minY && p.y() <= maxY;
    }

    /** Whether {@code p} lies at least {@code margin} metres inside the border. */
    public boolean containsWithMargin(Vec2 p, double margin) {
        return p.x() >= minX + margin && p.x() <= maxX - margin && p.y() >= minY + margin && p.y() <= maxY - margin;
    }
}
