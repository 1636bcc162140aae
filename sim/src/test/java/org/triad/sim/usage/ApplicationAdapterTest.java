package org.triad.sim.usage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.sim.ActionResult;
import org.triad.sim.FloorPlans;
import org.triad.sim.PersonSpec;
import org.triad.sim.Robot;
import org.triad.sim.RobotSpec;
import org.triad.sim.Simulation;

/**
 * How an application (outside the package) implements generated skill interfaces on the public API:
 * its domain objects carry the names of waypoints, items, doors and people.
 */
class ApplicationAdapterTest {

    record WayPoint(String name) {
    }

    record Item(String name) {
    }

    record Door(String name) {
    }

    /** Stand-in for a generated interface. */
    interface DeliverySkills {
        boolean move(WayPoint src, WayPoint dst);

        WayPoint loc();

        boolean load(Item i);

        boolean unload(Item i);

        boolean openDoor(Door d);
    }

    static final class SimulatedSkills implements DeliverySkills {
        final Simulation sim;
        final Robot robot;
        final List<ActionResult> log = new ArrayList<>();

        SimulatedSkills(Simulation sim, Robot robot) {
            this.sim = sim;
            this.robot = robot;
        }

        private boolean record(ActionResult r) {
            log.add(r);
            return r.success();
        }

        @Override
        public boolean move(WayPoint src, WayPoint dst) {
            if (!robot.isAt(src.name(), 0.7)) {
                return false;
            }
            // an edge of the plan is traversed as such; otherwise the simulator routes
            boolean edge = sim.plan().edge(src.name(), dst.name()).isPresent();
            return record(edge ? robot.moveAlong(List.of(src.name(), dst.name())) : robot.moveTo(dst.name()));
        }

        @Override
        public WayPoint loc() {
            return new WayPoint(robot.nearestWaypoint().name());
        }

        @Override
        public boolean load(Item i) {
            return record(robot.pick(i.name()));
        }

        @Override
        public boolean unload(Item i) {
            return record(robot.place(i.name()));
        }

        @Override
        public boolean openDoor(Door d) {
            return record(robot.openDoor(d.name()));
        }
    }

    @Test
    void deliveryPlanRunsOnTheSimulationAndRecoversFromAClosedDoor() {
        Simulation sim = Simulation.builder(FloorPlans.corridorWithRooms()).seed(11).build();
        sim.addPerson("visitor", "room5", PersonSpec.defaults()).wander();
        SimulatedSkills skills = new SimulatedSkills(sim, sim.addRobot("robot", "corridorWest", RobotSpec.defaults()));
        sim.closeDoor("room2Door");

        assertTrue(skills.move(new WayPoint("corridorWest"), new WayPoint("storage")));
        assertEquals(new WayPoint("storage"), skills.loc());
        assertTrue(skills.load(new Item("item3")));
        // the plan says: through the corridor and room2's door; that door is closed
        assertTrue(skills.move(new WayPoint("storage"), new WayPoint("room2Front")));
        assertFalse(skills.move(new WayPoint("room2Front"), new WayPoint("room2")));
        ActionResult failure = skills.log.get(skills.log.size() - 1);
        assertEquals(org.triad.sim.Failure.DOOR_CLOSED, failure.failure(), failure::toString);
        // replanning at the application level: open the door and go on
        assertTrue(skills.openDoor(new Door("room2Door")), () -> skills.log.toString());
        assertTrue(skills.move(skills.loc(), new WayPoint("room2")), () -> skills.log.toString());
        assertTrue(skills.unload(new Item("item3")));
        assertEquals("room2", sim.item("item3").room().orElseThrow().name());
        assertEquals(1, skills.log.stream().filter(r -> !r.success()).count(), skills.log::toString);
    }
}
