package org.triad.sim;

/** An item that exists when the simulation starts, at {@code position} (metres). */
public record ItemPlacement(String name, Vec2 position) {
}
