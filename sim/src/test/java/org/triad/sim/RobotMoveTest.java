package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class RobotMoveTest {

    @Test
    void reachesDistantWaypointAlongThePathWithinBoundedTime() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults());
        ActionResult r = robot.moveTo("room3");
        assertTrue(r.success(), r::toString);
        assertTrue(robot.isAt("room3", 0.1), () -> "ended at " + robot.position());
        double straightLine = Scenes.PLAN.waypoint("storage").position().distance(Scenes.PLAN.waypoint("room3").position());
        double minTime = straightLine / robot.spec().maxSpeed();
        assertTrue(r.duration() >= minTime, () -> "faster than the speed bound allows: " + r);
        assertTrue(r.duration() <= minTime + 10, () -> "too slow: " + r);
        assertEquals(r.endTime(), sim.time(), 1e-9);
    }

    @Test
    void speedNeverExceedsTheBoundEvenAmongWanderingPeople() {
        Simulation sim = Scenes.sim(3);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults().withMaxSpeed(0.8));
        sim.addPerson("p1", "room2Front", PersonSpec.defaults()).wander();
        sim.addPerson("p2", "room5", PersonSpec.defaults()).wander();
        for (String goal : List.of("room5", "room3", "corridorWest", "room6")) {
            ActionResult r = robot.moveTo(goal);
            assertTrue(r.success() || r.failure() == Failure.PATH_BLOCKED, r::toString);
        }
        double max = Scenes.maxStepSpeed(sim, "r");
        assertTrue(max <= 0.8 * 1.02, "max per-step speed " + max + " m/s exceeds 0.8 m/s");
        assertTrue(max >= 0.75, "the robot should reach cruise speed, max was " + max);
    }

    @Test
    void closedDoorOnTheRouteFailsTheMoveThenAnotherRouteSucceeds() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults());
        sim.closeDoor("room1-room2");
        ActionResult first = robot.moveTo("room2");
        assertFalse(first.success(), first::toString);
        assertEquals(Failure.DOOR_CLOSED, first.failure());
        assertTrue(first.message().contains("room1-room2"), first::toString);
        assertTrue(robot.room().map(Room::name).orElse("").equals("room1"), () -> "stopped in " + robot.room());
        assertEquals(java.util.Set.of("room1-room2"), robot.knownClosedDoors());
        List<Vec2> waited = sim.trace().robotPath("r");
        Vec2 end = waited.get(waited.size() - 1);
        Vec2 fiveSecondsBefore = waited.get(waited.size() - 1 - (int) (5 / sim.stepSeconds()));
        assertTrue(end.distance(fiveSecondsBefore) < 0.05, "the robot waited 5 s in front of the door");
        assertTrue(Math.abs(end.x() - 12) < 1.0, () -> "waited close to the door: " + end);

        int before = sim.trace().frames().size();
        ActionResult second = robot.moveTo("room2");
        assertTrue(second.success(), second::toString);
        assertTrue(second.action().contains("room1Door") && second.action().contains("room2Front"), second::toString);
        List<Vec2> path = sim.trace().robotPath("r").subList(before, sim.trace().frames().size());
        assertTrue(path.stream().anyMatch(p -> Scenes.PLAN.roomAt(p).map(Room::corridor).orElse(false)),
                "the detour goes through the corridor");
    }

    @Test
    void robotCanOpenTheClosedDoorItFailedAtUnlessLocked() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults());
        sim.closeDoor("room1-room2");
        sim.lockDoor("room1-room2", true);
        assertEquals(Failure.DOOR_CLOSED, robot.moveTo("room2").failure());
        ActionResult locked = robot.openDoor("room1-room2");
        assertEquals(Failure.DOOR_LOCKED, locked.failure(), locked::toString);
        sim.lockDoor("room1-room2", false);
        ActionResult opened = robot.openDoor("room1-room2");
        assertTrue(opened.success(), opened::toString);
        assertTrue(sim.door("room1-room2").isOpen());
        ActionResult far = sim.addRobot("r2", "room6", RobotSpec.defaults()).openDoor("room1-room2");
        assertEquals(Failure.OUT_OF_REACH, far.failure(), far::toString);
        ActionResult move = robot.moveAlong(List.of("room1-room2", "room2"));
        assertTrue(move.success(), move::toString);
    }

    @Test
    void scriptedDoorClosingWhileUnderWayIsDetected() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room6", RobotSpec.defaults());
        sim.at(3).closeDoor("room2Door");
        ActionResult r = robot.moveTo("room2");
        assertEquals(Failure.DOOR_CLOSED, r.failure(), r::toString);
        assertTrue(r.message().contains("room2Door"), r::toString);
        ActionResult detour = robot.moveTo("room2");
        assertTrue(detour.success(), detour::toString);
    }

    @Test
    void corridorBlockedByStandingPeopleBlocksThenClears() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        sim.at(1).blockSegment("room1Front", "room2Front", 4, 15);
        ActionResult r = robot.moveAlong(List.of("corridorEast"));
        assertTrue(r.success(), r::toString);
        assertTrue(r.duration() > 22.8 / 1.0 + 3, () -> "the robot should have waited for the blockers: " + r);
        // while blocked it stayed west of the row of people at x = 12 and kept clear of them
        int blockers = sim.trace().personNames().indexOf("blocker1.1");
        double stillSeconds = 0;
        for (TraceFrame f : sim.trace().frames()) {
            Vec2 rp = Scenes.robotAt(f, 0);
            if (f.time() > 2 && f.time() < 16) {
                assertTrue(rp.x() < 12 - 0.5, "robot passed the blockers at t=" + f.time() + ": " + rp);
                if (rp.x() > 9) {
                    stillSeconds += f.time() > 2 ? sim.stepSeconds() : 0;
                }
            }
            for (int i = blockers; i < blockers + 4; i++) {
                Vec2 pp = Scenes.personAt(f, i);
                if (pp != null) {
                    assertTrue(pp.distance(rp) > 0.25 + 0.3 - 0.02, "robot ran into a blocker at t=" + f.time());
                }
            }
        }
        assertTrue(stillSeconds > 5, "the robot waited near the blockers, " + stillSeconds + " s");
    }

    @Test
    void persistentlyBlockedCorridorFailsAfterTheBlockedTimeoutWithReason() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "corridorWest", RobotSpec.defaults().withTimeouts(5, 10));
        sim.at(0).blockSegment("room1Front", "room2Front", 4, 300);
        ActionResult r = robot.moveTo("corridorEast");
        assertEquals(Failure.PATH_BLOCKED, r.failure(), r::toString);
        assertTrue(r.message().contains("blocker1"), r::toString);
        assertTrue(r.duration() < 60, r::toString);
        assertTrue(robot.position().x() < 12, () -> "" + robot.position());
    }

    @Test
    void noRouteWhenAllKnownRoutesAreClosed() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room3", RobotSpec.defaults());
        sim.closeDoor("room3Door");
        sim.closeDoor("room2-room3");
        sim.runFor(0.1);
        assertEquals(java.util.Set.of("room2-room3", "room3Door"), robot.knownClosedDoors());
        ActionResult r = robot.moveTo("corridorEast");
        assertEquals(Failure.NO_ROUTE, r.failure(), r::toString);
        assertEquals(r.startTime(), r.endTime());
    }
}
