package org.triad.sim;

/** A straight wall between two points (metres); its thickness is {@link FloorPlan#wallThickness()}. */
public record Wall(Vec2 a, Vec2 b) {
}
