package org.triad.sim;

/** A named node of the waypoint graph at {@code position} (metres). */
public record Waypoint(String name, Vec2 position) {
}
