package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.triad.refarc.fleet.FleetContext;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.RobotPlatformProvider;

/**
 * Scheme {@code sim} of the hospital application: {@code sim:N} connects N simulated couriers, each in
 * a hospital simulation of its own (the models' Morning situation), paced at 10 simulated seconds per
 * wall-clock second so that people can follow them on a map; {@code sim:N@S} paces at S times real
 * time, {@code sim:N@max} runs as fast as the machine can.
 *
 * <p>One simulation per robot, not one shared: the simulation advances virtual time inside a robot's
 * blocking action and is not thread-safe, so robots sharing one would have to take turns step by step
 * instead of working in parallel, and one robot's fault scenario would disturb the others.
 */
public final class SimulatedHospitalFleet implements RobotPlatformProvider {
    /** Simulated seconds per wall-clock second unless the argument says otherwise. */
    public static final double DEFAULT_SPEED = 10;
    /** More robots than this is a typo, not a fleet. */
    public static final int MAX_ROBOTS = 100;

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
        return "sim:N[@SPEED|@max]  N simulated hospital couriers, each on its own floor (default speed "
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
        List<FleetRobot> robots = new ArrayList<>();
        for (int i = 1; i <= n; i++) {
            robots.add(new SimulatedHospitalRobot("sim-" + i, i, speed));
        }
        return robots;
    }
}
