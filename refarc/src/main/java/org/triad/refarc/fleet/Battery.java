package org.triad.refarc.fleet;

/**
 * A robot's battery as its platform reports it (VDA 5050 {@code batteryState}).
 *
 * @param charge   state of charge, percent (0 to 100)
 * @param charging whether it is charging now
 */
public record Battery(double charge, boolean charging) {
}
