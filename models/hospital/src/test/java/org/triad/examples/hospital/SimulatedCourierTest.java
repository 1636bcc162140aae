package org.triad.examples.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/** The robotics expert's IRobot/IWorld on the simulator, action by action. */
class SimulatedCourierTest {
    private final HospitalSimulation h = new HospitalSimulation(1);
    private final HospitalObjects o = h.objects();
    private final SimulatedCourier courier = h.courier();
    private final SimulatedBuilding building = h.building();

    @Test
    void movesAlongModelEdgesOnlyFromWhereTheRobotIs() {
        assertEquals(o.room("lobby"), courier.loc());
        assertFalse(courier.move(o.waypoint("c4"), o.waypoint("c1")), "not at c4");
        assertFalse(courier.move(o.room("lobby"), o.waypoint("c5")), "no corridor from the lobby to c5");
        assertEquals(0.0, h.sim().time(), "refusals take no time");
        assertEquals(List.of("REFUSED", "REFUSED"), h.platformLog().entries().stream().map(PlatformLog.Entry::failure).toList());

        assertTrue(courier.move(o.room("lobby"), o.waypoint("c4")));
        assertTrue(courier.move(o.waypoint("c4"), o.waypoint("c1")));
        assertEquals(o.waypoint("c1"), courier.loc());
        assertTrue(courier.robot().isAt("c1", 0.2));
    }

    @Test
    void picksAndDropsItemsWhereTheRobotIs() {
        assertFalse(courier.pick(o.item("gauze"), o.room("storage")), "the robot is in the lobby");
        for (String[] leg : new String[][] { {"lobby", "c4"}, {"c4", "c1"}, {"c1", "storage"} }) {
            assertTrue(courier.move(o.waypoint(leg[0]), o.waypoint(leg[1])));
        }
        assertTrue(building.itemAt(o.item("bandage"), o.room("storage")));
        assertEquals(0, courier.load());
        assertTrue(courier.pick(o.item("bandage"), o.room("storage")));
        assertTrue(courier.carries(o.item("bandage")));
        assertEquals(2, courier.load(), "the bandage's weight, kg");
        assertFalse(building.itemAt(o.item("bandage"), o.room("storage")), "carried, not lying there");
        assertTrue(courier.pick(o.item("gauze"), o.room("storage")), "a second item rides along");
        assertEquals(3, courier.load(), "the weights summed");
        assertFalse(courier.drop(o.item("syringe"), o.room("storage")));
        assertEquals("NOT_CARRYING", last().failure());
        assertTrue(courier.move(o.room("storage"), o.waypoint("c1")));
        assertTrue(courier.drop(o.item("bandage"), o.waypoint("c1")));
        assertEquals(1, courier.load(), "the gauze is still carried");
        assertTrue(building.itemAt(o.item("bandage"), o.waypoint("c1")));
    }

    @Test
    void aClosedDoorFailsTheMoveAndThenTheEdgeIsNoLongerAdjacent() {
        h.sim().closeDoor(HospitalFloor.FIRE_DOOR);
        for (String[] leg : new String[][] { {"lobby", "c4"}, {"c4", "c1"}, {"c1", "c2"} }) {
            assertTrue(courier.move(o.waypoint(leg[0]), o.waypoint(leg[1])));
        }
        assertTrue(building.adj(o.waypoint("c2"), o.waypoint("c3")), "not seen yet");
        assertFalse(courier.move(o.waypoint("c2"), o.waypoint("c3")));
        assertEquals("DOOR_CLOSED", last().failure());
        assertEquals(o.waypoint("c2"), courier.loc(), "it stopped in front of the door, nearer c2");
        assertFalse(building.adj(o.waypoint("c2"), o.waypoint("c3")));
        assertFalse(building.adj(o.waypoint("c3"), o.waypoint("c2")));
        assertFalse(courier.move(o.waypoint("c2"), o.waypoint("c3")), "the implementation does not drive into a door it knows closed");
        assertEquals("REFUSED", last().failure());
    }

    @Test
    void guidesAPersonWhoStaysWithTheRobot() {
        assertEquals(o.room("lobby"), building.personAt(o.person("alice")));
        assertTrue(courier.guide(o.person("alice"), o.room("lobby"), o.waypoint("c4")));
        assertEquals(o.waypoint("c4"), building.personAt(o.person("alice")));
        assertTrue(courier.guide(o.person("alice"), o.waypoint("c4"), o.waypoint("c5")));
        assertEquals(o.waypoint("c5"), building.personAt(o.person("alice")));
        assertTrue(h.sim().person("alice").position().distance(courier.robot().position()) < 2.5);
    }

    @Test
    void walkingNeedsTheRobotToFollowThePersonFirst() {
        assertFalse(building.walk(o.person("alice"), o.room("lobby"), o.waypoint("c4")));
        assertEquals("REFUSED", last().failure());
        assertFalse(courier.startFollowing(o.person("bob"), o.room("lobby")), "Bob is in ward 2");
        assertTrue(courier.startFollowing(o.person("alice"), o.room("lobby")));
        assertTrue(courier.following(o.person("alice")));
        assertFalse(courier.following(o.person("bob")));
        assertTrue(building.walk(o.person("alice"), o.room("lobby"), o.waypoint("c4")));
        assertEquals(o.waypoint("c4"), building.personAt(o.person("alice")));
        assertEquals(o.waypoint("c4"), courier.loc());
    }

    @Test
    void theWorldListsTheModelsObjects() {
        assertEquals(List.of("c1", "c2", "c3", "c4", "c5", "c6", "c0", "c7", "lift0", "lift1", "d1", "d2"),
                building.wayPoints().stream().map(w -> w.name()).toList());
        assertEquals(List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby", "pharmacy", "ward4", "ward5"),
                building.rooms().stream().map(r -> r.name()).toList());
        assertEquals(List.of("gauze", "syringe", "bandage", "insulin"), building.items().stream().map(i -> i.name()).toList());
        assertEquals(List.of("pharmacyDoor"), building.doors().stream().map(d -> d.name()).toList());
        assertEquals(List.of("lift"), building.lifts().stream().map(l -> l.name()).toList());
        assertEquals(List.of("alice", "bob"), building.persons().stream().map(p -> p.name()).toList());
        assertEquals("X-ray", o.room("xray").getName());
    }

    @Test
    void theBuildingOpensThePharmacyDoorAndTheLiftCarriesTheRobotToFloorOne() {
        assertFalse(building.adj(o.waypoint("c0"), o.room("pharmacy")), "a doorway, not a corridor");
        assertTrue(building.doorway(o.door("pharmacyDoor"), o.waypoint("c0"), o.room("pharmacy")));
        assertTrue(building.landing(o.lift("lift"), o.waypoint("c7")) && building.landing(o.lift("lift"), o.waypoint("d1")));
        assertFalse(h.sim().door("pharmacyDoor").isOpen(), "closed until the building opens it");
        for (String[] leg : new String[][] { {"lobby", "c4"}, {"c4", "c0"} }) {
            assertTrue(courier.move(o.waypoint(leg[0]), o.waypoint(leg[1])));
        }
        assertTrue(building.passDoor(o.door("pharmacyDoor"), o.waypoint("c0"), o.room("pharmacy")), h.platformLog().entries().toString());
        assertTrue(courier.pick(o.item("insulin"), o.room("pharmacy")));
        assertTrue(building.passDoor(o.door("pharmacyDoor"), o.room("pharmacy"), o.waypoint("c0")), h.platformLog().entries().toString());
        h.sim().runFor(5);
        assertFalse(h.sim().door("pharmacyDoor").isOpen(), "closed again behind the robot");
        for (String[] leg : new String[][] { {"c0", "c1"}, {"c1", "c2"}, {"c2", "c3"}, {"c3", "c7"} }) {
            assertTrue(courier.move(o.waypoint(leg[0]), o.waypoint(leg[1])));
        }
        double before = h.sim().time();
        assertTrue(building.ride(o.lift("lift"), o.waypoint("c7"), o.waypoint("d1")), h.platformLog().entries().toString());
        assertTrue(h.sim().time() - before >= HospitalFloor.LIFT_SECONDS_PER_FLOOR, "the ride takes the lift's travel time");
        assertEquals(o.waypoint("d1"), courier.loc());
        assertEquals(1, HospitalFloor.floorOf(courier.loc().name()));
        assertTrue(courier.carries(o.item("insulin")), "what the robot carries rides with it");
        assertTrue(courier.move(o.waypoint("d1"), o.waypoint("d2")) && courier.move(o.waypoint("d2"), o.room("ward4")));
        assertTrue(courier.drop(o.item("insulin"), o.room("ward4")));
        assertTrue(building.itemAt(o.item("insulin"), o.room("ward4")));
    }

    @Test
    void aLiftThatStopsBetweenFloorsFailsTheRideWithTheReason() {
        h.sim().breakLift(HospitalFloor.LIFT);
        assertFalse(building.ride(o.lift("lift"), o.waypoint("c7"), o.waypoint("d1")), "not at c7");
        for (String[] leg : new String[][] { {"lobby", "c4"}, {"c4", "c5"}, {"c5", "c6"}, {"c6", "c7"} }) {
            assertTrue(courier.move(o.waypoint(leg[0]), o.waypoint(leg[1])));
        }
        assertFalse(building.ride(o.lift("lift"), o.waypoint("c7"), o.waypoint("d1")));
        assertEquals("LIFT_FAULT: lift 'lift' stopped between floors 0 and 1", h.platformLog().lastFailure().orElseThrow());
        assertEquals(o.waypoint("lift0"), courier.loc(), "stuck in the cabin it entered on floor 0");
    }

    private PlatformLog.Entry last() {
        List<PlatformLog.Entry> e = h.platformLog().entries();
        return e.get(e.size() - 1);
    }
}
