package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class BatteryTest {

    @Test
    void drivingDrainsPerMetreAnEmptyBatteryStopsTheMoveAndADockRecharges() {
        Simulation sim = Scenes.sim(1);
        Robot r = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        r.setBattery(new Battery(100, 10, 50, 1)); // 10 m of driving
        ActionResult move = r.moveTo("corridorEast");
        assertEquals(Failure.BATTERY_EMPTY, move.failure(), move::toString);
        double driven = r.position().x() - 0.6;
        assertTrue(driven > 9.9 && driven < 10.2, "gave up after about 10 m, not " + driven);
        assertTrue(r.battery().isEmpty());
        assertFalse(r.battery().isCharging());
        sim.runFor(2); // brakes to a stop (an empty battery still brakes)
        sim.addDock("dock", r.position());
        sim.runFor(1);
        assertTrue(r.battery().isCharging());
        assertEquals(50, r.battery().percent(), 2, "50 W for 1 s into 100 J");
        sim.runFor(2);
        assertEquals(100, r.battery().percent(), 1e-9);
        assertFalse(r.battery().isCharging(), "full: no longer charging");
        assertThrows(IllegalArgumentException.class, () -> new Battery(0, 1, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new Battery(1, 1, 1, 1.5));
    }

    @Test
    void theDefaultBatteryDrainsFiftyJoulesPerMetre() {
        Simulation sim = Scenes.sim(1);
        Robot r = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        assertTrue(r.moveTo("corridorEast").success());
        double metres = r.position().distance(Scenes.PLAN.waypoint("corridorWest").position());
        assertEquals(100 - 100 * 50 * metres / 360_000, r.battery().percent(), 0.01);
    }
}
