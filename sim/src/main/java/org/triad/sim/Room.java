package org.triad.sim;

/**
 * A named axis-aligned area of the floor plan (bounds in metres). Corridors are rooms with
 * {@code corridor == true}; the flag only affects pictures and queries, not physics.
 */
public record Room(String name, Rect bounds, boolean corridor) {
}
