package org.triad.sim;

/**
 * Something that happened: an activity ending (robot actions), a scripted event, a door change.
 * {@code time} in virtual seconds, {@code position} in metres.
 */
public record TraceEvent(double time, String actor, String action, Vec2 position, boolean success, String detail) {
}
