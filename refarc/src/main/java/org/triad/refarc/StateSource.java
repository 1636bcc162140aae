package org.triad.refarc;

import org.triad.runtime.app.State;

/**
 * The application-specific way to observe the world: the generated StateProvider behaviour that
 * queries the robot's and the world's properties ({@code IRobot}, {@code IWorld}).
 */
@FunctionalInterface
public interface StateSource {
    /** A snapshot of the world now; never null. May throw if the robot or world cannot be queried. */
    State currentState() throws Exception;
}
