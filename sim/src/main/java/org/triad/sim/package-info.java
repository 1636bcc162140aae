/**
 * Application-independent 2D simulation of a building with mobile robots, people, doors and items,
 * on the dyn4j physics engine. Units are SI throughout: metres, seconds, m/s, m/s^2, radians.
 *
 * <ul>
 *   <li>{@link org.triad.sim.FloorPlan} (built with {@link org.triad.sim.FloorPlan#builder()}) holds
 *       rooms, corridors, derived walls, doorways, a named waypoint graph and initial items;
 *       {@link org.triad.sim.FloorPlans} has a ready-made corridor-with-rooms example.</li>
 *   <li>{@link org.triad.sim.Simulation} advances virtual time in fixed steps, deterministically for a
 *       seed; it owns robots, people, items and doors and schedules events via
 *       {@link org.triad.sim.Simulation#at(double)}.</li>
 *   <li>{@link org.triad.sim.Robot} activities (move, pick, place, open door, guide, follow, wait) block
 *       until they succeed or fail and return an {@link org.triad.sim.ActionResult} with a
 *       {@link org.triad.sim.Failure} reason.</li>
 *   <li>{@link org.triad.sim.Trace} records poses per step and events; {@link org.triad.sim.TracePicture},
 *       {@link org.triad.sim.GifReplay} and {@link org.triad.sim.HtmlReplay} render it.</li>
 * </ul>
 *
 * Public methods fail fast with {@link java.lang.IllegalArgumentException} on bad arguments (unknown
 * names, NaN, negative durations or speeds...). Nothing here is thread-safe.
 */
package org.triad.sim;
