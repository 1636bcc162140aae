package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.sim.Battery;
import org.triad.sim.Robot;

/** The building's staff swap the battery of a courier that has stood empty for the given time, where it stands, and say so. No broker. */
class BatteryRescueTest {
    @Test
    void aCourierEmptyForTheGivenTimeGetsAChargedBatteryWhereItStandsAndTheRescueIsPrinted() {
        HospitalBuilding building = new HospitalBuilding(1, false, List.of("courier-1", "courier-2", "courier-3"));
        Robot empty = building.sim().robot("courier-2");
        Battery b = empty.battery();
        empty.setBattery(new Battery(b.capacityJoules(), b.joulesPerMetre(), b.chargingWatts(), 0));
        List<String> lines = new ArrayList<>();
        BatteryRescue.serve(building, 30, lines::add);
        var at = empty.position();
        building.sim().runFor(29);
        assertTrue(lines.isEmpty(), "not before 30 s: " + lines);
        assertEquals(0, empty.battery().percent(), 1e-9);
        building.sim().runFor(2);
        assertEquals(1, lines.size(), lines.toString());
        assertTrue(lines.get(0).matches("rescue courier-2 at lobby(\\.\\d+)? \\(.*\\) t=30\\.\\d s: its battery was empty for 30 s; staff swapped it for a charged one"),
                lines.get(0));
        assertEquals(100, empty.battery().percent(), 1e-9);
        assertTrue(empty.position().distance(at) < 0.01, "where it stands");
        assertEquals(100, building.sim().robot("courier-3").battery().percent(), 1e-9, "the others untouched");
        building.sim().runFor(60);
        assertEquals(1, lines.size(), "once");
    }
}
