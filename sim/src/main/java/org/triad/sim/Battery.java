package org.triad.sim;

import java.util.Locale;

/**
 * A robot's battery: drains {@link #joulesPerMetre()} for every metre the robot drives (standing, handling items and
 * waiting cost nothing: the simulation models traction only), and charges at {@link #chargingWatts()} while the robot
 * stands still (below 0.05 m/s) within {@value Simulation#DOCK_RANGE} m of a dock ({@link Simulation#addDock}). A
 * robot whose battery is empty cannot drive: its move fails with {@link Failure#BATTERY_EMPTY}. SI units: joules,
 * metres, watts. The defaults: 360 kJ (100 Wh) full, 50 J/m (7.2 km per charge), 500 W (12 min from empty to full).
 */
public final class Battery {
    private final double capacity;
    private final double joulesPerMetre;
    private final double chargingWatts;
    private double energy;
    private boolean charging;

    /**
     * @param capacityJoules energy when full, J (&gt; 0)
     * @param joulesPerMetre energy per metre driven, J/m (&gt;= 0)
     * @param chargingWatts  charging power at a dock, W (&gt;= 0)
     * @param chargeFraction initial charge, 0..1
     * @throws IllegalArgumentException for values out of range
     */
    public Battery(double capacityJoules, double joulesPerMetre, double chargingWatts, double chargeFraction) {
        this.capacity = Checks.positive("battery capacity (J)", capacityJoules);
        this.joulesPerMetre = Checks.nonNegative("drain (J/m)", joulesPerMetre);
        this.chargingWatts = Checks.nonNegative("charging power (W)", chargingWatts);
        if (!(chargeFraction >= 0 && chargeFraction <= 1)) {
            throw new IllegalArgumentException("initial charge is a fraction 0..1, not " + chargeFraction);
        }
        this.energy = capacity * chargeFraction;
    }

    /** Full, 360 kJ, 50 J/m, 500 W. */
    public static Battery defaults() {
        return new Battery(360_000, 50, 500, 1);
    }

    public double capacityJoules() {
        return capacity;
    }

    public double joulesPerMetre() {
        return joulesPerMetre;
    }

    public double chargingWatts() {
        return chargingWatts;
    }

    /** Energy left, J. */
    public double energyJoules() {
        return energy;
    }

    /** State of charge, percent 0..100 (VDA 5050 {@code batteryCharge}). */
    public double percent() {
        return 100 * energy / capacity;
    }

    /** Whether the robot charges now (at a dock, standing still, not full). */
    public boolean isCharging() {
        return charging;
    }

    public boolean isEmpty() {
        return energy <= 0;
    }

    void drive(double metres) {
        energy = Math.max(0, energy - metres * joulesPerMetre);
    }

    void dock(boolean atDock, double seconds) {
        charging = atDock && energy < capacity && chargingWatts > 0;
        if (charging) {
            energy = Math.min(capacity, energy + chargingWatts * seconds);
        }
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "Battery[%.1f%%%s]", percent(), charging ? ", charging" : "");
    }
}
