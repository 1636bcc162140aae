package org.triad.sim;

/**
 * A walking person modelled as a disc, SI units.
 *
 * @param radius          body radius, m
 * @param maxSpeed        walking speed bound, m/s
 * @param maxAcceleration acceleration bound, m/s^2
 */
public record PersonSpec(double radius, double maxSpeed, double maxAcceleration) {

    /** @throws IllegalArgumentException on a non-positive or non-finite value */
    public PersonSpec {
        Checks.positive("person radius (m)", radius);
        Checks.positive("person max speed (m/s)", maxSpeed);
        Checks.positive("person max acceleration (m/s^2)", maxAcceleration);
    }

    /** Radius 0.25 m, 1.0 m/s, 1.5 m/s^2. */
    public static PersonSpec defaults() {
        return new PersonSpec(0.25, 1.0, 1.5);
    }

    public PersonSpec withMaxSpeed(double metresPerSecond) {
        return new PersonSpec(radius, metresPerSecond, maxAcceleration);
    }
}
