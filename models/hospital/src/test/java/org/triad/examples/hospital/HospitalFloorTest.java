package org.triad.examples.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.triad.sim.Vec2;

class HospitalFloorTest {
    private final HospitalFloor floor = new HospitalFloor();

    @Test
    void everyModelWaypointIsASimulatorWaypointOfTheSameName() {
        for (String w : floor.modelWaypoints()) {
            assertTrue(floor.plan().hasWaypoint(w), w);
        }
        for (String room : HospitalFloor.ROOMS) {
            assertEquals(room, floor.waypointAt(floor.plan().waypoint(room).position()));
        }
    }

    @Test
    void theRingGivesTwoWaysRoundAndTheSideCorridorsGoRoundTheCorners() {
        assertEquals(Optional.of(List.of("c1", "nw", "sw", "c4")), floor.route("c1", "c4"));
        assertEquals(Optional.of(List.of("c4", "sw", "nw", "c1")), floor.route("c4", "c1"));
        assertEquals(Optional.of(List.of("c6", "se", "ne", "c3")), floor.route("c6", "c3"));
        assertEquals(Optional.of(List.of("storage", "c1")), floor.route("storage", "c1"));
        assertEquals(Optional.empty(), floor.route("c1", "c3"), "no corridor skips c2");
        assertEquals(Optional.empty(), floor.route("storage", "xray"), "rooms open onto the corridor only");
        assertEquals(List.of(HospitalFloor.FIRE_DOOR), floor.doorsOn(floor.route("c2", "c3").orElseThrow()));
        assertEquals(List.of("storageDoor"), floor.doorsOn(floor.route("c1", "storage").orElseThrow()));
        assertEquals(List.of(), floor.doorsOn(floor.route("c4", "c1").orElseThrow()));
    }

    @Test
    void positionsBelongToTheirRoomOrTheNearestCorridorWaypoint() {
        assertEquals("lobby", floor.waypointAt(new Vec2(7, 1)));
        assertEquals("c2", floor.waypointAt(new Vec2(14.5, 14)));
        assertEquals("c3", floor.waypointAt(new Vec2(17, 14)));
        assertEquals("c4", floor.waypointAt(new Vec2(2, 7)), "the west corridor at its south end");
        assertEquals("c0", floor.waypointAt(new Vec2(1.2, 9.5)), "the west corridor before the pharmacy's door");
        assertEquals("lift1", floor.waypointAt(new Vec2(36, 10)), "the lift's cabin on floor 1");
        assertEquals("d2", floor.waypointAt(new Vec2(46, 10)), "floor 1's corridor");
        // someone brought to c4 and waiting in the lobby's doorway is still at c4; further away, in the lobby
        assertEquals("c4", floor.waypointAt(new Vec2(4, 4.8), "c4"));
        assertEquals("lobby", floor.waypointAt(new Vec2(4, 4.8), null));
        assertEquals("lobby", floor.waypointAt(new Vec2(4, 2.5), "c4"));
    }
}
