package org.triad.examples.hospital.fleet;

import java.util.List;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.refarc.fleet.FloorMap;
import org.triad.sim.SimulationClock;

/**
 * The one simulated hospital of a service's {@code sim:N} fleet: a {@link HospitalBuilding} whose clock steps one
 * dyn4j simulation for all N couriers, so that they share one world (one gauze, Alice in one room) and meet in
 * its corridors. Its floor map is taken under the clock's lock and kept for {@value #MAP_MILLIS} ms, so that the
 * operator page's many readers cost the simulation one snapshot per period, not one each. The clock stops when
 * the last courier is closed.
 */
final class SimulatedHospital {
    /** Wall-clock milliseconds a floor map is reused before a new one is taken. */
    static final long MAP_MILLIS = 200;

    private final HospitalBuilding building;
    private final SimulationClock clock;
    private int open;
    private FloorMap map;
    private long mapNanos;

    SimulatedHospital(long seed, List<String> names, double speed) {
        building = new HospitalBuilding(seed, false, names);
        clock = building.start(speed);
        open = names.size();
    }

    HospitalBuilding building() {
        return building;
    }

    SimulationClock clock() {
        return clock;
    }

    /** The building's floor now (at most {@value #MAP_MILLIS} ms old), with every courier under its own name. */
    synchronized FloorMap map() {
        long now = System.nanoTime();
        if (map == null || now - mapNanos > MAP_MILLIS * 1_000_000L) {
            if (clock.isRunning()) {
                map = clock.call(SimulatedHospitalRobot::snapshot);
            } else if (map == null) {
                map = SimulatedHospitalRobot.snapshot(building.sim());
            }
            mapNanos = now;
        }
        return map;
    }

    /** One courier is done with the building; the last one stops its clock. */
    synchronized void release() {
        if (--open == 0) {
            building.stop();
        }
    }
}
