package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

class ScriptedEventsTest {

    @Test
    void doorReopenedWhileTheRobotWaitsLetsTheMoveSucceedOnTheSameRoute() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults().withTimeouts(8, 20));
        sim.closeDoor("room1-room2");
        sim.at(9).openDoor("room1-room2");
        ActionResult r = robot.moveTo("room2");
        assertTrue(r.success(), r::toString);
        assertTrue(r.action().contains("room1, room2]"), r::toString);
        assertTrue(r.duration() > 9, "it waited for the door: " + r);
        assertTrue(robot.knownClosedDoors().isEmpty());
    }

    @Test
    void doorClosesOnlyOnceNobodyStandsInTheDoorway() {
        Simulation sim = Scenes.sim(1);
        Person p = sim.addPerson("p", "room1Door", PersonSpec.defaults());
        sim.at(3).run("walk away", s -> p.walkTo("room1"));
        sim.closeDoor("room1Door");
        Door door = sim.door("room1Door");
        assertTrue(door.isOpen() && door.isClosing());
        assertTrue(sim.runUntil(() -> !door.isOpen(), 10));
        assertTrue(sim.time() > 3, "closed after the person left, at " + sim.time());
        TraceEvent closed = sim.trace().events().stream().filter(e -> e.action().equals("door room1Door closed"))
                .findFirst().orElseThrow();
        assertEquals(sim.time(), closed.time(), sim.stepSeconds() + 1e-9, "recorded in the step the door closed");
    }

    @Test
    void eventsRunInTimeOrderThenSchedulingOrder() {
        Simulation sim = Scenes.sim(1);
        List<String> seen = new ArrayList<>();
        sim.at(2).run("b", s -> seen.add("b@" + s.time()));
        sim.at(1).run("a", s -> seen.add("a@" + s.time()));
        sim.at(2).run("c", s -> seen.add("c@" + s.time()));
        sim.runFor(3);
        assertEquals(3, seen.size());
        assertTrue(seen.get(0).startsWith("a@1.0"), seen::toString);
        assertTrue(seen.get(1).startsWith("b@2.0") && seen.get(2).startsWith("c@2.0"), seen::toString);
    }

    @Test
    void blockingCallsFromEventsAreRefused() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults());
        sim.at(0.5).run("bad", s -> robot.moveTo("room1"));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> sim.runFor(1));
        assertTrue(e.getMessage().contains("not allowed inside a step"), e.getMessage());
    }

    @Test
    void guidedPersonWhoLeavesIsReportedLost() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room4Door", RobotSpec.defaults());
        sim.addPerson("visitor", "room4", PersonSpec.defaults());
        sim.at(4).run("visitor leaves", s -> s.removePerson("visitor"));
        ActionResult r = robot.guide("visitor", "room3");
        assertEquals(Failure.PERSON_LOST, r.failure(), r::toString);
        assertFalse(sim.person("visitor").isPresent());
        assertTrue(sim.people().isEmpty());
    }

    @Test
    void lockedDoorCannotBeOpenedUntilUnlocked() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room1", RobotSpec.defaults());
        sim.closeDoor("room1-room2");
        sim.at(1).lockDoor("room1-room2").at(10).unlockDoor("room1-room2");
        assertEquals(Failure.DOOR_CLOSED, robot.moveTo("room2").failure());
        assertEquals(Failure.DOOR_LOCKED, robot.openDoor("room1-room2").failure());
        sim.runUntil(() -> !sim.door("room1-room2").isLocked(), 20);
        assertTrue(robot.openDoor("room1-room2").success());
        assertTrue(robot.moveTo("room2").success());
    }
}
