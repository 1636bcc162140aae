package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/** Two floors side by side in one world, joined by a lift whose cabin carries a robot between its landings. */
class LiftTest {
    /** Floor 0: a hall (0..8 m) with the cabin east of it; floor 1 the same 20 m further east. */
    static FloorPlan twoFloors() {
        FloorPlan.Builder b = FloorPlan.builder();
        for (int f = 0; f < 2; f++) {
            double x = 20 * f;
            b.corridor("hall" + f, x, 0, x + 8, 3).room("cabin" + f, x + 8, 0, x + 11, 3)
                    .door("liftDoor" + f, "hall" + f, "cabin" + f, x + 8, 1.5)
                    .waypoint("h" + f, x + 4, 1.5).waypoint("in" + f, x + 9.5, 1.5).edge("h" + f, "in" + f);
        }
        return b.build();
    }

    private static Simulation sim() {
        Simulation s = Simulation.builder(twoFloors()).seed(1).build();
        s.addLift("lift", List.of(new Lift.Landing(0, "cabin0", "liftDoor0"), new Lift.Landing(1, "cabin1", "liftDoor1")), 5, 1);
        return s;
    }

    @Test
    void aRobotRidesFromFloorZeroToFloorOne() {
        Simulation s = sim();
        Lift lift = s.lift("lift");
        Robot r = s.addRobot("r", "h0", RobotSpec.defaults());
        assertTrue(s.door("liftDoor1").isOpen(), "the cabin stands at floor 1, its door open there");
        assertFalse(s.door("liftDoor0").isOpen());

        assertTrue(s.requestLift("lift", 0).isEmpty());
        assertTrue(s.runUntil(() -> lift.currentFloor().equals(java.util.Optional.of(0)), 30), "the lift came down");
        double rideStart = s.time();
        assertTrue(s.door("liftDoor0").isOpen());
        assertTrue(r.moveTo("in0").success());
        assertTrue(s.requestLift("lift", 1).isEmpty());
        assertEquals(Lift.Motion.MOVING, lift.motion());
        assertTrue(s.runUntil(() -> lift.motion() == Lift.Motion.STOPPED, 30));
        assertTrue(s.plan().room("cabin1").bounds().contains(r.position()), "the robot came up with the cabin: " + r.position());
        assertTrue(s.time() - rideStart >= 5, "one floor takes 5 simulated seconds");
        assertTrue(r.moveTo("h1").success(), "the robot leaves the cabin on floor 1");
        assertEquals(2, lift.rides());
    }

    @Test
    void aBrokenLiftStopsBetweenFloorsWithTheRobotInside() {
        Simulation s = sim();
        Lift lift = s.lift("lift");
        Robot r = s.addRobot("r", "in1", RobotSpec.defaults());
        s.at(0).breakLift("lift");
        s.runFor(0.1);
        assertTrue(s.requestLift("lift", 0).isEmpty());
        assertTrue(s.runUntil(() -> lift.motion() == Lift.Motion.FAULT, 30));
        assertEquals("lift 'lift' stopped between floors 1 and 0", lift.fault().orElseThrow());
        assertTrue(lift.currentFloor().isEmpty());
        assertEquals("lift 'lift' stopped between floors 1 and 0", s.requestLift("lift", 1).orElseThrow(), "it refuses every request");
        s.runFor(10);
        assertTrue(s.plan().room("cabin1").bounds().contains(r.position()), "nobody arrives anywhere");
        assertFalse(s.door("liftDoor0").isOpen());
        assertFalse(s.door("liftDoor1").isOpen());

        s.repairLift("lift");
        assertEquals(java.util.Optional.of(1), lift.currentFloor());
        assertTrue(s.door("liftDoor1").isOpen());
    }

    @Test
    void badLiftsAreRefused() {
        Simulation s = Simulation.builder(twoFloors()).build();
        assertThrows(IllegalArgumentException.class, () -> s.addLift("l", List.of(new Lift.Landing(0, "cabin0", "liftDoor0")), 5, 0));
        assertThrows(IllegalArgumentException.class, () -> s.addLift("l",
                List.of(new Lift.Landing(0, "cabin0", "liftDoor0"), new Lift.Landing(1, "nowhere", "liftDoor1")), 5, 0));
        assertThrows(IllegalArgumentException.class, () -> s.addLift("l",
                List.of(new Lift.Landing(0, "cabin0", "liftDoor0"), new Lift.Landing(1, "cabin1", "liftDoor1")), 5, 7));
        s.addLift("l", List.of(new Lift.Landing(0, "cabin0", "liftDoor0"), new Lift.Landing(1, "cabin1", "liftDoor1")), 5, 0);
        assertThrows(IllegalArgumentException.class, () -> s.requestLift("l", 3));
        assertThrows(IllegalArgumentException.class, () -> s.requestLift("other", 0));
    }
}
