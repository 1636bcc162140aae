package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

class ArgumentValidationTest {

    private static void rejects(String expectedInMessage, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().contains(expectedInMessage),
                () -> "message '" + e.getMessage() + "' should mention '" + expectedInMessage + "'");
    }

    @Test
    void specsRejectNegativeNaNAndZero() {
        rejects("max speed", () -> RobotSpec.defaults().withMaxSpeed(-1));
        rejects("max acceleration", () -> RobotSpec.defaults().withMaxAcceleration(Double.NaN));
        rejects("capacity", () -> RobotSpec.defaults().withCapacity(0));
        rejects("person max speed", () -> PersonSpec.defaults().withMaxSpeed(0));
        rejects("finite", () -> new Vec2(Double.NaN, 1));
        rejects("finite", () -> new Vec2(1, Double.POSITIVE_INFINITY));
        rejects("minX < maxX", () -> new Rect(2, 0, 1, 1));
    }

    @Test
    void simulationRejectsUnknownNamesAndBadValues() {
        Simulation sim = Scenes.sim(1);
        Robot r = sim.addRobot("r", "storage", RobotSpec.defaults());
        rejects("unknown waypoint 'nowhere'", () -> r.moveTo("nowhere"));
        rejects("unknown waypoint 'nowhere'", () -> r.moveAlong(List.of("storage", "nowhere")));
        rejects("no edge", () -> r.moveAlong(List.of("storage", "room6")));
        rejects("at least one", () -> r.moveAlong(List.of()));
        rejects("unknown item 'gold'", () -> r.pick("gold"));
        rejects("unknown door 'hatch'", () -> r.openDoor("hatch"));
        rejects("unknown person 'ghost'", () -> r.guide("ghost", "room1"));
        sim.addPerson("p", "room2", PersonSpec.defaults());
        rejects("min distance", () -> r.follow("p", -1, 2, 10));
        rejects("timeout", () -> r.follow("p", 1, 2, Double.NaN));
        rejects("must be <", () -> r.follow("p", 2, 1, 10));
        rejects("wait", () -> r.waitFor(-0.5));
        rejects("duplicate", () -> sim.addRobot("p", "room3", RobotSpec.defaults()));
        rejects("overlap a wall", () -> sim.addRobot("r2", new Vec2(6.0, 1.0), RobotSpec.defaults()));
        rejects("overlap 'r'", () -> sim.addRobot("r3", new Vec2(3.2, 2.5), RobotSpec.defaults()));
        rejects("outside every room", () -> sim.addItem("x", new Vec2(-5, -5)));
        rejects("unknown room 'attic'", () -> sim.itemsIn("attic"));
        rejects("step", () -> Simulation.builder(Scenes.PLAN).stepSeconds(0));
        rejects("smaller step", () -> Simulation.builder(Scenes.PLAN).stepSeconds(0.1).build()
                .addPerson("runner", "room1", PersonSpec.defaults().withMaxSpeed(3)));
        rejects("duration", () -> sim.runFor(Double.NaN));
        sim.runFor(1);
        rejects("in the past", () -> sim.at(0.5));
        rejects("unknown door", () -> sim.at(2).closeDoor("nope"));
        rejects("at least one person", () -> sim.at(2).blockSegment("room1Front", "room2Front", 0, 5));
        rejects("blocking duration", () -> sim.at(2).blockSegment("room1Front", "room2Front", 2, -5));
        rejects("unknown waypoint", () -> sim.at(2).blockSegment("room1Front", "x", 2, 5));
    }

    @Test
    void floorPlanBuilderRejectsInconsistentPlans() {
        rejects("at least one room", () -> FloorPlan.builder().build());
        rejects("not on a wall shared", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).room("b", 4, 0, 8, 4)
                .door("d", "a", "b", 3, 2).build());
        rejects("unknown room 'c'", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).door("d", "a", "c", 4, 2));
        rejects("outside every room", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).waypoint("w", 5, 5).build());
        rejects("duplicate waypoint", () -> FloorPlan.builder().waypoint("w", 1, 1).waypoint("w", 2, 2));
        rejects("to itself", () -> FloorPlan.builder().edge("w", "w"));
        rejects("unknown waypoint 'v'", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).waypoint("w", 1, 1)
                .edge("w", "v").build());
        rejects("share no wall", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).room("b", 5, 0, 8, 4).opening("a", "b"));
        rejects("door width", () -> FloorPlan.builder().room("a", 0, 0, 4, 4).room("b", 4, 0, 8, 4)
                .door("d", "a", "b", 4, 2, -1));
        rejects("room width", () -> FloorPlans.corridorWithRooms(List.of("a"), List.of(), 1, 5, 2));
    }
}
