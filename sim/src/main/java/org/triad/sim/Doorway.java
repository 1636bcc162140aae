package org.triad.sim;

/**
 * A door in the wall shared by two rooms. {@code center} lies on the shared wall (metres);
 * {@code width} is the clear opening in metres; {@code horizontal} tells whether the wall runs
 * along the x axis. The simulation turns each doorway into a {@link Door} that opens and closes.
 */
public record Doorway(String name, String roomA, String roomB, Vec2 center, double width, boolean horizontal,
                      boolean initiallyOpen) {

    /** One end of the door leaf. */
    public Vec2 end1() {
        return horizontal ? new Vec2(center.x() - width / 2, center.y()) : new Vec2(center.x(), center.y() - width / 2);
    }

    /** The other end of the door leaf. */
    public Vec2 end2() {
        return horizontal ? new Vec2(center.x() + width / 2, center.y()) : new Vec2(center.x(), center.y() + width / 2);
    }
}
