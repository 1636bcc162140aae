package org.triad.sim;

/**
 * Poses after one step. Arrays are indexed like {@link Trace#robotNames()}, {@link Trace#personNames()}
 * {@link Trace#itemNames()} at recording time, door states like {@link FloorPlan#doorways()} (later-added entities are missing from earlier frames);
 * coordinates in metres, headings in radians; NaN marks an absent person or a removed item. Each robot's battery is its
 * state of charge, percent of a full battery ({@link Battery#percent()}).
 */
public record TraceFrame(double time, double[] robotX, double[] robotY, double[] robotHeading, double[] personX,
                         double[] personY, double[] itemX, double[] itemY, boolean[] doorOpen, double[] robotBattery) {
}
