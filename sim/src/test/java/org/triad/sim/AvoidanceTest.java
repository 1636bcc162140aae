package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class AvoidanceTest {

    /** Smallest gap between the robot's and the person's discs over the whole trace, metres. */
    private static double minGap(Simulation sim, Robot robot, Person person) {
        int pi = sim.trace().personNames().indexOf(person.name());
        double min = Double.POSITIVE_INFINITY;
        for (TraceFrame f : sim.trace().frames()) {
            min = Math.min(min, Scenes.robotAt(f, 0).distance(Scenes.personAt(f, pi)) - robot.radius() - person.radius());
        }
        return min;
    }

    @Test
    void robotSidestepsAPersonWalkingHeadOnWhoDoesNotGiveWay() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        Person p = sim.addPerson("p", "corridorEast", PersonSpec.defaults());
        p.setYieldsToRobots(false);
        p.walkTo("corridorWest");
        ActionResult r = robot.moveTo("corridorEast");
        assertTrue(r.success(), r::toString);
        assertTrue(minGap(sim, robot, p) > 0.02, "robot touched the person, gap " + minGap(sim, robot, p));
        assertTrue(sim.runUntil(() -> !p.isWalking(), 30), "the person got past too");
        double maxLateral = sim.trace().robotPath("r").stream().mapToDouble(v -> Math.abs(v.y() - 6.2)).max().orElse(0);
        assertTrue(maxLateral > 0.3, "the robot sidestepped, max lateral offset " + maxLateral);
    }

    @Test
    void personStandingInADoorwayStepsAsideForTheRobot() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room1", RobotSpec.defaults());
        Person p = sim.addPerson("p", "room1Door", PersonSpec.defaults());
        ActionResult r = robot.moveTo("room4");
        assertTrue(r.success(), r::toString);
        assertTrue(r.duration() < 20, r::toString);
        assertTrue(minGap(sim, robot, p) > 0.02, "robot touched the person");
        assertTrue(p.position().distance(Scenes.PLAN.waypoint("room1Door").position()) > 0.5, "the person moved away");
    }

    @Test
    void accelerationStaysWithinTheBoundWithoutContacts() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults().withMaxAcceleration(0.5));
        assertTrue(robot.moveTo("room6").success());
        List<Vec2> path = sim.trace().robotPath("r");
        double dt = sim.stepSeconds();
        double max = 0;
        for (int i = 2; i < path.size(); i++) {
            Vec2 v1 = path.get(i - 1).minus(path.get(i - 2)).times(1 / dt);
            Vec2 v2 = path.get(i).minus(path.get(i - 1)).times(1 / dt);
            max = Math.max(max, v2.minus(v1).length() / dt);
        }
        assertTrue(max <= 0.5 * 1.05, "max acceleration " + max + " m/s^2 exceeds 0.5");
    }
}
