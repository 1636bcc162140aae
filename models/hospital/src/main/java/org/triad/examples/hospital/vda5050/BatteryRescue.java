package org.triad.examples.hospital.vda5050;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.sim.Battery;
import org.triad.sim.Robot;

/**
 * The hospital's staff in the simulated building: a courier whose battery has been empty for a while gets a charged one
 * where it stands, and the building says so in one line, {@code rescue courier-3 at c5 (12.3, 4.0) t=2801.0 s: its battery
 * was empty for 300 s; staff swapped it for a charged one}, which a benchmark counts. An empty courier cannot drive, so
 * without staff it stood in the others' way for good (master control has it lost there meanwhile, and nobody is sent
 * into it). A swap where it stands rather than a push to the dock: the dock is a place for one robot that others queue
 * for in the reservation table, and a courier carried onto it would take a place promised to another; the swapped
 * courier reports its charge, and master control puts it back on the map where it stands at its next drive.
 * Off unless {@code ./triad robot --rescue-after SECONDS} asks for it: a building without staff shows what an empty
 * battery does.
 */
final class BatteryRescue {
    private final HospitalBuilding building;
    private final double afterSeconds;
    private final Consumer<String> out;
    /** When each courier's battery was first seen empty, simulated seconds. */
    private final Map<String, Double> emptySince = new HashMap<>();

    private BatteryRescue(HospitalBuilding building, double afterSeconds, Consumer<String> out) {
        this.building = building;
        this.afterSeconds = afterSeconds;
        this.out = out;
    }

    /** Watches the building's couriers at every step from now on (register before the clock starts). */
    static void serve(HospitalBuilding building, double afterSeconds, Consumer<String> out) {
        BatteryRescue r = new BatteryRescue(building, afterSeconds, out);
        building.sim().addStepListener(r::check);
    }

    /** On the stepping thread, after a step: the world holds still while it looks. */
    private void check() {
        double now = building.sim().time();
        for (HospitalBuilding.Courier c : building.couriers()) {
            Robot robot = c.robot();
            Battery b = robot.battery();
            if (!b.isEmpty() || b.isCharging()) {
                emptySince.remove(c.name());
                continue;
            }
            double since = emptySince.computeIfAbsent(c.name(), k -> now);
            if (now - since >= afterSeconds) {
                robot.setBattery(new Battery(b.capacityJoules(), b.joulesPerMetre(), b.chargingWatts(), 1));
                emptySince.remove(c.name());
                out.accept(String.format(Locale.ROOT, "rescue %s at %s (%.1f, %.1f) t=%.1f s: its battery was empty for %.0f s; staff swapped it for a charged one",
                        c.name(), building.floor().waypointAt(robot.position()), robot.position().x(), robot.position().y(), now, now - since));
            }
        }
    }
}
