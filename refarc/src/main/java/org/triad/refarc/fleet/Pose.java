package org.triad.refarc.fleet;

/**
 * Where a robot is, as its platform reports it (a VDA 5050 state's {@code agvPosition}, a simulator).
 *
 * @param x     metres, in the map's frame
 * @param y     metres, in the map's frame
 * @param theta heading, radians
 * @param mapId the map (e.g. floor) the coordinates are on, or null when the platform names none
 */
public record Pose(double x, double y, double theta, String mapId) {
}
