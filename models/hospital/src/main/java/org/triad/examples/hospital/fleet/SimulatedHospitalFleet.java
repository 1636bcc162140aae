package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.refarc.fleet.FleetContext;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.RobotPlatformProvider;

/**
 * Scheme {@code sim} of the hospital application: {@code sim:N} connects N simulated couriers in one simulated
 * hospital (one dyn4j simulation of the models' Morning situation with its own clock, the same building as
 * {@code ./triad robot --count N} puts on a broker): one gauze, Alice in one room, robots that meet in the
 * corridors. The clock runs at 10 simulated seconds per wall-clock second so that people can follow the robots on
 * a map; {@code sim:N@S} paces at S times real time, {@code sim:N@max} runs as fast as the machine can. Couriers
 * are named {@code sim-1} to {@code sim-N}; the first starts at the lobby's waypoint, the others park along the
 * walls of the lobby and then of other rooms. One {@code sim:} spec per service: it is the building.
 */
public final class SimulatedHospitalFleet implements RobotPlatformProvider {
    /** Simulated seconds per wall-clock second unless the argument says otherwise. */
    public static final double DEFAULT_SPEED = 10;
    /** More robots than this is a typo, not a fleet. */
    public static final int MAX_ROBOTS = 100;
    /** The seed of the people's choices: the same service, the same building. */
    static final long SEED = 1;
    /** Whether this provider made the building already (the service loads its providers once). */
    private boolean connected;

    @Override
    public String application() {
        return "Hospital";
    }

    @Override
    public String scheme() {
        return "sim";
    }

    @Override
    public String usage() {
        return "sim:N[@SPEED|@max]  N simulated hospital couriers in one simulated hospital (default speed "
                + (int) DEFAULT_SPEED + "x real time)";
    }

    @Override
    public List<FleetRobot> connect(String argument, FleetContext context) {
        String[] parts = argument.split("@", 2);
        int n;
        try {
            n = Integer.parseInt(parts[0].trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("sim:N takes a number of robots, not '" + parts[0] + "'");
        }
        if (n < 1 || n > MAX_ROBOTS) {
            throw new IllegalArgumentException("sim:N takes 1 to " + MAX_ROBOTS + " robots, not " + n);
        }
        double speed = DEFAULT_SPEED;
        if (parts.length == 2) {
            String s = parts[1].trim().toLowerCase(Locale.ROOT);
            try {
                speed = s.equals("max") ? Double.POSITIVE_INFINITY : Double.parseDouble(s);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("sim:N@SPEED takes a number or 'max', not '" + parts[1] + "'");
            }
            if (!(speed > 0)) {
                throw new IllegalArgumentException("sim:N@SPEED needs a speed above 0, not " + parts[1]);
            }
        }
        if (connected) {
            throw new IllegalArgumentException("the simulated hospital is one building: give all its couriers in one sim:N");
        }
        List<String> names = new ArrayList<>();
        for (int i = 1; i <= n; i++) {
            names.add("sim-" + i);
        }
        SimulatedHospital hospital = new SimulatedHospital(SEED, names, speed);
        connected = true;
        List<FleetRobot> robots = new ArrayList<>();
        for (HospitalBuilding.Courier c : hospital.building().couriers()) {
            robots.add(new SimulatedHospitalRobot(hospital, c));
        }
        return robots;
    }
}
