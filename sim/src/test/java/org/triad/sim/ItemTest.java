package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

class ItemTest {

    @Test
    void pickAndPlaceMoveTheItemToAnotherRoom() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room1", RobotSpec.defaults());
        Item item = sim.item("item1");
        assertEquals("storage", item.room().orElseThrow().name());
        assertEquals(List.of("item1", "item2", "item3"), sim.itemsIn("storage").stream().map(Item::name).toList());

        ActionResult far = robot.pick("item1");
        assertEquals(Failure.OUT_OF_REACH, far.failure(), far::toString);

        assertTrue(robot.moveTo("storage").success());
        ActionResult pick = robot.pick("item1");
        assertTrue(pick.success(), pick::toString);
        assertEquals(robot.spec().handlingSeconds(), pick.duration(), sim.stepSeconds() * 1.5);
        assertEquals(List.of(item), robot.carried());
        assertEquals(robot, item.holder().orElseThrow());

        assertEquals(Failure.CAPACITY_EXCEEDED, robot.pick("item2").failure());
        assertEquals(Failure.NOT_CARRYING, robot.place("item2").failure());

        assertTrue(robot.moveTo("room4").success());
        assertEquals(robot.position(), item.position(), "a carried item moves with the robot");
        ActionResult place = robot.place("item1");
        assertTrue(place.success(), place::toString);
        assertTrue(robot.carried().isEmpty());
        assertEquals("room4", item.room().orElseThrow().name());
        assertEquals("room4", item.nearestWaypoint().name());
        assertEquals(List.of(item), sim.itemsIn("room4"));
        assertEquals(List.of("item2", "item3"), sim.itemsIn("storage").stream().map(Item::name).toList());
        assertTrue(item.holder().isEmpty());

        ActionResult again = robot.pick("item1");
        assertTrue(again.success(), "a placed item can be picked again: " + again);
    }

    @Test
    void approachBringsTheRobotWithinReachOfAnItemAwayFromWaypoints() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "corridorWest", RobotSpec.defaults());
        sim.addItem("linen", new Vec2(22.8, 0.9));
        assertEquals(Failure.OUT_OF_REACH, robot.pick("linen").failure());
        ActionResult r = robot.approach("linen");
        assertTrue(r.success(), r::toString);
        double d = robot.position().distance(sim.item("linen").position());
        assertTrue(d <= robot.spec().reach() && d > 0.5, "robot stopped " + d + " m from the item");
        assertTrue(robot.pick("linen").success());
        assertEquals(Failure.ITEM_UNAVAILABLE, robot.approach("linen").failure());
    }

    @Test
    void scriptedRemovalMakesTheItemUnavailable() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "room1", RobotSpec.defaults());
        sim.at(2).removeItem("item2");
        assertTrue(robot.moveTo("storage").success());
        ActionResult pick = robot.pick("item2");
        assertEquals(Failure.ITEM_UNAVAILABLE, pick.failure(), pick::toString);
        assertTrue(sim.item("item2").isRemoved());
        assertTrue(sim.item("item2").room().isEmpty());
    }

    @Test
    void removingACarriedItemEmptiesTheRobot() {
        Simulation sim = Scenes.sim(1);
        Robot robot = sim.addRobot("r", "storage", RobotSpec.defaults().withCapacity(2));
        assertTrue(robot.pick("item1").success());
        assertTrue(robot.pick("item2").success());
        sim.at(sim.time() + 1).removeItem("item1");
        robot.waitFor(2);
        assertEquals(List.of(sim.item("item2")), robot.carried());
    }
}
