package org.triad.examples.hospital;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.sim.Vec2;

/** The lobby's parking spots give every parked courier a clear way out (issue #21: no contact in the lobby). */
class HospitalBuildingParkingTest {
    private static final double CLEARANCE = 0.68;

    @Test
    void everyParkedCourierHasAClearWayToTheLobbysWaypointAndOut() {
        HospitalFloor floor = new HospitalFloor();
        Vec2 waypoint = floor.plan().waypoint("lobby").position();
        Vec2 c4 = floor.plan().waypoint("c4").position();
        List<Vec2> spots = HospitalBuilding.LOBBY_SPOTS;
        for (Vec2 s : spots) {
            assertEquals("lobby", floor.waypointAt(s), s + " lies in the lobby");
            assertTrue(distanceToSegment(s, waypoint, c4) >= LobbyParking.WAY_OUT_CLEARANCE, s + " stands 1 m off the way out through the door");
            assertTrue(distanceToSegment(HospitalFloor.PEOPLE.get("alice"), s, waypoint) >= CLEARANCE, "Alice stands off the way from " + s);
            for (Vec2 other : spots) {
                if (other != s) {
                    assertTrue(distanceToSegment(other, s, waypoint) >= CLEARANCE, "the way from " + s + " passes " + other + " too close");
                }
            }
        }
    }

    @Test
    void nobodyParksWithinReachOfTheDock() {
        assertTrue(LobbyParking.spots().stream().noneMatch(s -> LobbyParking.besideTaken(LobbyParking.DOCK, s::equals)),
                "a courier arriving at the dock never stops short of it for one parked beside it");
        assertTrue(LobbyParking.besideTaken("lobby.1", "lobby.2"::equals), "lobby.1 and lobby.2 stand 0.95 m apart");
    }

    @Test
    void twentyCouriersStartFifteenInTheLobbyTheFirstOnTheDockThenOneToARoomInTurn() {
        List<String> names = new ArrayList<>();
        for (int i = 1; i <= 20; i++) {
            names.add("courier-" + i);
        }
        HospitalBuilding building = new HospitalBuilding(1, false, names);
        assertEquals(15, HospitalBuilding.LOBBY_SPOTS.size());
        List<String> places = List.copyOf(LobbyParking.places().keySet());
        assertEquals(LobbyParking.DOCK, places.get(0));
        for (int i = 0; i < names.size(); i++) {
            Vec2 at = building.sim().robot(names.get(i)).position();
            List<String> rooms = List.of("ward3", "ward2", "storage", "xray", "ward1");
            String room = i < 15 ? "lobby" : rooms.get((i - 15) % rooms.size());
            assertEquals(room, building.floor().waypointAt(at), names.get(i) + " starts in " + room);
            if (i < 15) {
                assertEquals(java.util.Optional.of(places.get(i)), LobbyParking.placeAt(at), names.get(i) + " at " + at + " stands on " + places.get(i));
            }
        }
        // the dock is where the building charges: courier-1 on it charges, courier-2 on a spot does not
        assertTrue(building.sim().docks().get(HospitalBuilding.DOCK).distance(building.sim().robot("courier-1").position()) < 0.05);
        assertTrue(building.sim().contacts().isEmpty(), "nobody touches at the start: " + building.sim().contacts());
    }

    @Test
    void theWayFromTheDockAndEverySpotToTheLobbysWaypointIsALaneOfTheFloorAndNoShortcutForAnyoneElse() {
        HospitalFloor floor = new HospitalFloor();
        for (String place : LobbyParking.places().keySet()) {
            assertEquals(java.util.Optional.of(List.of(place, "lobby")), floor.route(place, "lobby"), place);
            assertEquals("lobby", LobbyParking.waypointOf(place));
        }
        // a leaf never shortens a way: the planner's routes between the models' waypoints do not pass a spot
        assertEquals(java.util.Optional.of(List.of("lobby", "c4")), floor.route("lobby", "c4"));
        assertEquals("c4", LobbyParking.waypointOf("c4"));
    }

    private static double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
        Vec2 ab = b.minus(a);
        double t = Math.max(0, Math.min(1, p.minus(a).dot(ab) / ab.dot(ab)));
        return p.distance(new Vec2(a.x() + t * ab.x(), a.y() + t * ab.y()));
    }
}
