package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

class DeterminismTest {

    /** A delivery with wandering people and scripted events; returns the finished simulation. */
    static Simulation delivery(long seed) {
        Simulation sim = Scenes.sim(seed);
        Robot robot = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        sim.addPerson("a", "room1Front", PersonSpec.defaults()).wander();
        sim.addPerson("b", "room5", PersonSpec.defaults()).wander();
        sim.addPerson("c", "room2", PersonSpec.defaults().withMaxSpeed(0.7)).wander();
        sim.at(20).closeDoor("room1-room2").at(60).openDoor("room1-room2");
        robot.moveTo("storage");
        robot.pick("item1");
        robot.moveTo("room2");
        robot.place("item1");
        robot.moveTo("room6");
        return sim;
    }

    @Test
    void sameSeedGivesIdenticalTracesStepByStep() {
        Simulation a = delivery(42);
        Simulation b = delivery(42);
        List<TraceFrame> fa = a.trace().frames();
        List<TraceFrame> fb = b.trace().frames();
        assertEquals(fa.size(), fb.size());
        for (int i = 0; i < fa.size(); i++) {
            TraceFrame x = fa.get(i);
            TraceFrame y = fb.get(i);
            assertEquals(x.time(), y.time());
            assertArrayEquals(x.robotX(), y.robotX(), "robot x differs at step " + i);
            assertArrayEquals(x.robotY(), y.robotY(), "robot y differs at step " + i);
            assertArrayEquals(x.personX(), y.personX(), "person x differs at step " + i);
            assertArrayEquals(x.personY(), y.personY(), "person y differs at step " + i);
            assertArrayEquals(x.itemX(), y.itemX(), "item x differs at step " + i);
        }
        assertEquals(a.trace().events(), b.trace().events());
    }

    @Test
    void differentSeedsMakePeopleWalkDifferently() {
        Simulation a = delivery(1);
        Simulation b = delivery(2);
        int n = Math.min(a.trace().frames().size(), b.trace().frames().size());
        boolean differ = false;
        for (int i = 0; i < n && !differ; i++) {
            differ = !Arrays.equals(a.trace().frames().get(i).personX(), b.trace().frames().get(i).personX());
        }
        assertTrue(differ, "people's random walks should depend on the seed");
    }
}
