package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PeopleTest {

    @Test
    void personWalksToAWaypointWithinItsSpeedBound() {
        Simulation sim = Scenes.sim(1);
        Person p = sim.addPerson("p", "room4", PersonSpec.defaults().withMaxSpeed(1.2));
        p.walkTo("room2");
        assertTrue(p.isWalking());
        assertTrue(sim.runUntil(() -> !p.isWalking(), 60));
        assertTrue(p.position().distance(Scenes.PLAN.waypoint("room2").position()) < 0.2, () -> "" + p.position());
        double max = 0;
        Vec2 prev = null;
        for (TraceFrame f : sim.trace().frames()) {
            Vec2 pos = Scenes.personAt(f, 0);
            if (prev != null) {
                max = Math.max(max, pos.distance(prev) / sim.stepSeconds());
            }
            prev = pos;
        }
        assertTrue(max <= 1.2 * 1.02 && max > 1.0, "person max speed " + max);
    }

    @Test
    void guidedPersonArrivesNearTheRobotsDestination() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room4Door", RobotSpec.defaults());
        Person visitor = sim.addPerson("visitor", "room4", PersonSpec.defaults().withMaxSpeed(0.9));
        ActionResult r = robot.guide("visitor", "room3");
        assertTrue(r.success(), r::toString);
        assertTrue(robot.isAt("room3", 0.1));
        double d = visitor.position().distance(Scenes.PLAN.waypoint("room3").position());
        assertTrue(d < 2.5, "visitor ended " + d + " m from the destination");
        assertEquals("room3", visitor.room().orElseThrow().name());
        assertFalse(visitor.isWalking());
    }

    @Test
    void guidingWaitsForASlowPerson() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room4Door", RobotSpec.defaults());
        sim.addPerson("slow", "room4", PersonSpec.defaults().withMaxSpeed(0.3));
        ActionResult r = robot.guide("slow", "room6");
        assertTrue(r.success(), r::toString);
        double path = 14 + 2 * 2.8;
        assertTrue(r.duration() > path / 0.5, "robot must adapt to the 0.3 m/s person: " + r);
        for (TraceFrame f : sim.trace().frames()) {
            double gap = Scenes.robotAt(f, 0).distance(Scenes.personAt(f, 0));
            assertTrue(gap < 4.0, "the person fell " + gap + " m behind at t=" + f.time());
        }
    }

    @Test
    void followingKeepsTheDistanceWithinTheBandWhileThePersonWalks() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", new Vec2(1.0, 6.2), RobotSpec.defaults());
        Person p = sim.addPerson("p", new Vec2(3.0, 6.2), PersonSpec.defaults().withMaxSpeed(0.8));
        p.walkTo("room3");
        ActionResult r = robot.follow("p", 0.8, 2.5, 120);
        assertTrue(r.success(), r::toString);
        assertTrue(r.duration() > 20, r::toString);
        double min = Double.POSITIVE_INFINITY;
        double max = 0;
        for (TraceFrame f : sim.trace().frames()) {
            double d = Scenes.robotAt(f, 0).distance(Scenes.personAt(f, 0));
            min = Math.min(min, d);
            max = Math.max(max, d);
        }
        assertTrue(min >= 0.8 && max <= 2.5, "distance left the band [0.8, 2.5] m: min " + min + ", max " + max);
        assertEquals("room3", robot.room().orElseThrow().name(), "the robot followed the person into the room");
    }

    @Test
    void followingFailsWhenThePersonOutrunsTheRobot() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", new Vec2(1.0, 6.2), RobotSpec.defaults().withMaxSpeed(0.4));
        Person p = sim.addPerson("p", new Vec2(3.0, 6.2), PersonSpec.defaults().withMaxSpeed(1.5));
        p.walkTo("room6");
        ActionResult r = robot.follow("p", 0.8, 2.5, 120);
        assertEquals(Failure.PERSON_LOST, r.failure(), r::toString);
    }
}
