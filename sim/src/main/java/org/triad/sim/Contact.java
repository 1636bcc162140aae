package org.triad.sim;

import java.util.Locale;

/**
 * Two robots touched: their names (in the order they were added), where (the midpoint between their centres,
 * metres) and when (virtual seconds).
 */
public record Contact(String first, String second, Vec2 position, double time) {
    /** {@code contact courier-1 courier-2 at (12.03, 6.20) t=41.35 s}: the line a building prints. */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "contact %s %s at (%.2f, %.2f) t=%.2f s", first, second, position.x(), position.y(), time);
    }
}
