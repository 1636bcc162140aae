package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class MultiRobotTest {

    @Test
    void twoRobotsMoveAtTheSameTimeAndPassEachOther() {
        Simulation sim = Scenes.sim(1);
        Robot a = sim.addRobot("a", "corridorWest", RobotSpec.defaults());
        Robot b = sim.addRobot("b", "corridorEast", RobotSpec.defaults());
        PendingAction goingEast = a.startMoveTo("corridorEast");
        assertFalse(goingEast.isDone());
        assertThrows(IllegalStateException.class, () -> a.moveTo("storage"), "a is busy");
        ActionResult west = b.moveTo("corridorWest");
        ActionResult east = goingEast.await();
        assertTrue(west.success(), west::toString);
        assertTrue(east.success(), east::toString);
        assertTrue(east.startTime() < west.endTime() && west.startTime() < east.endTime(), "the moves overlapped");
        double minGap = Double.POSITIVE_INFINITY;
        for (TraceFrame f : sim.trace().frames()) {
            minGap = Math.min(minGap, Scenes.robotAt(f, 0).distance(Scenes.robotAt(f, 1)) - 0.6);
        }
        assertTrue(minGap > 0, "robots touched: gap " + minGap);
        assertEquals(2, sim.trace().events().size());
    }

    @Test
    void immediateFailureOfAStartedMoveIsDoneAtOnce() {
        Simulation sim = Scenes.sim(1);
        Robot r = sim.addRobot("r", "room3", RobotSpec.defaults());
        sim.closeDoor("room3Door");
        sim.closeDoor("room2-room3");
        sim.step();
        PendingAction p = r.startMoveAlong(List.of("room3", "room3Door"));
        assertFalse(p.isDone());
        assertEquals(Failure.DOOR_CLOSED, p.await().failure());
        PendingAction none = r.startMoveTo("corridorEast");
        assertTrue(none.isDone());
        assertEquals(Failure.NO_ROUTE, none.result().orElseThrow().failure());
    }
}
