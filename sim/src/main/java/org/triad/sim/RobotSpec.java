package org.triad.sim;

/**
 * Physical and behavioural parameters of a disc-shaped holonomic robot, SI units.
 *
 * @param radius              body radius, m
 * @param maxSpeed            speed bound, m/s
 * @param maxAcceleration     acceleration bound, m/s^2
 * @param reach               max distance from robot centre to an item or door centre to handle it, m
 * @param capacity            how many items it can carry at once
 * @param doorWaitSeconds     how long it waits in front of a closed door before failing the move, s
 * @param blockedSeconds      how long it tolerates no progress (blocked corridor) before failing the move, s
 * @param handlingSeconds     virtual time a pick, place, door open or close takes, s
 */
public record RobotSpec(double radius, double maxSpeed, double maxAcceleration, double reach, int capacity,
                        double doorWaitSeconds, double blockedSeconds, double handlingSeconds) {

    /** @throws IllegalArgumentException on a non-positive or non-finite value */
    public RobotSpec {
        Checks.positive("robot radius (m)", radius);
        Checks.positive("robot max speed (m/s)", maxSpeed);
        Checks.positive("robot max acceleration (m/s^2)", maxAcceleration);
        Checks.positive("robot reach (m)", reach);
        if (capacity < 1) {
            throw new IllegalArgumentException("robot capacity must be >= 1, got " + capacity);
        }
        Checks.nonNegative("door wait (s)", doorWaitSeconds);
        Checks.positive("blocked timeout (s)", blockedSeconds);
        Checks.nonNegative("handling time (s)", handlingSeconds);
    }

    /** Radius 0.3 m, 1.0 m/s, 0.8 m/s^2, reach 1.0 m, 1 item, 5 s door wait, 20 s blocked timeout, 2 s handling. */
    public static RobotSpec defaults() {
        return new RobotSpec(0.3, 1.0, 0.8, 1.0, 1, 5, 20, 2);
    }

    public RobotSpec withMaxSpeed(double metresPerSecond) {
        return new RobotSpec(radius, metresPerSecond, maxAcceleration, reach, capacity, doorWaitSeconds, blockedSeconds,
                handlingSeconds);
    }

    public RobotSpec withMaxAcceleration(double metresPerSecond2) {
        return new RobotSpec(radius, maxSpeed, metresPerSecond2, reach, capacity, doorWaitSeconds, blockedSeconds,
                handlingSeconds);
    }

    public RobotSpec withCapacity(int items) {
        return new RobotSpec(radius, maxSpeed, maxAcceleration, reach, items, doorWaitSeconds, blockedSeconds,
                handlingSeconds);
    }

    public RobotSpec withTimeouts(double doorWait, double blocked) {
        return new RobotSpec(radius, maxSpeed, maxAcceleration, reach, capacity, doorWait, blocked, handlingSeconds);
    }
}
