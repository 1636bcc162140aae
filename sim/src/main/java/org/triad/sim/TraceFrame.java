package org.triad.sim;

/**
 * Poses after one step. Arrays are indexed like {@link Trace#robotNames()}, {@link Trace#personNames()}
 * {@link Trace#itemNames()} at recording time, door states like {@link FloorPlan#doorways()} (later-added entities are missing from earlier frames);
 * coordinates in metres, headings in radians; NaN marks an absent person or a removed item.
 */
public record TraceFrame(double time, double[] robotX, double[] robotY, double[] robotHeading, double[] personX,
                         double[] personY, double[] itemX, double[] itemY, boolean[] doorOpen) {
}
