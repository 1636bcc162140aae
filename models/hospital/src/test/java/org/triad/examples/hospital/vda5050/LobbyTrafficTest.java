package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.triad.building.traffic.Decision;
import org.triad.building.traffic.ReservationTable;
import org.triad.building.traffic.TrafficMap;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.LobbyParking;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * The lobby's parking spots and dock as nodes of the hospital's traffic map (issue #21): the table knows where in the
 * lobby each courier stands, nobody waits on the way out, couriers queue for the dock in the table, and a models' move
 * into the lobby ends at a free spot. No broker: the table and the routes as master control uses them.
 */
class LobbyTrafficTest {
    private static final TrafficMap MAP = HospitalTraffic.map(new HospitalFloor());

    @Test
    void everySpotAndTheDockIsAStopNodeForOneAndTheHallsCentreIsNoPlaceToWait() {
        for (String place : LobbyParking.places().keySet()) {
            assertTrue(MAP.isStop(place), place);
            assertEquals(1, MAP.node(place).capacity(), place);
            assertEquals(java.util.Set.of(LobbyParking.HALL), MAP.neighbours(place), place);
        }
        assertFalse(MAP.isStop(LobbyParking.HALL), "nobody waits in the hall's centre, everyone's way in and out");
        assertEquals(1, MAP.node(LobbyParking.HALL).capacity());
    }

    @Test
    void aCourierLeavingItsSpotHoldsTheHallAndTheWayOutAtOnceAndTheNextWaitsOnItsOwnSpot() {
        ReservationTable t = new ReservationTable(MAP, () -> 0);
        t.place("courier-1", LobbyParking.DOCK);
        t.place("courier-2", "lobby.1");
        t.place("courier-3", "lobby.2");
        Decision first = t.request("courier-2", List.of("lobby.1", "lobby", "c4"));
        assertInstanceOf(Decision.Granted.class, first);
        assertEquals(List.of("lobby.1", "lobby", "c4"), ((Decision.Granted) first).stretch(), "one stretch from the spot to c4");
        Decision second = t.request("courier-3", List.of("lobby.2", "lobby", "c4"));
        assertInstanceOf(Decision.Waiting.class, second, "the hall is courier-2's");
        assertEquals("lobby.2", t.decisionPoint("courier-3"), "it waits where it parked, off the way out");
        // courier-2 is through the hall and on along the corridor: courier-3 goes
        t.passed("courier-2", "lobby");
        assertTrue(t.passed("courier-2", "c4").granted().isEmpty(), "c4 is courier-2's while it stands there");
        assertInstanceOf(Decision.Granted.class, t.request("courier-2", List.of("c4", "c5")));
        ReservationTable.Changes c = t.passed("courier-2", "c5");
        assertTrue(c.granted().stream().anyMatch(g -> g.robot().equals("courier-3")), "courier-3 granted once courier-2 has left c4: " + c);
    }

    @Test
    void couriersQueueForTheDockInTheTableAndTheOneChargingDrivesOffToAFreeSpot() {
        ReservationTable t = new ReservationTable(MAP, () -> 0);
        t.place("courier-1", LobbyParking.DOCK);
        t.place("courier-2", "lobby.3");
        Decision wait = t.request("courier-2", List.of("lobby.3", "lobby", LobbyParking.DOCK));
        assertInstanceOf(Decision.Waiting.class, wait, "the dock is courier-1's");
        assertTrue(t.waits().get(0).reason().contains(LobbyParking.DOCK), t.waits().toString());
        // courier-1 charged and parks on a free spot: granted (courier-2 waits on its spot, not in the hall)
        Decision off = t.request("courier-1", List.of(LobbyParking.DOCK, "lobby", "lobby.4"));
        assertInstanceOf(Decision.Granted.class, off);
        t.passed("courier-1", "lobby");
        ReservationTable.Changes c = t.passed("courier-1", "lobby.4");
        assertTrue(c.granted().stream().anyMatch(g -> g.robot().equals("courier-2")), "courier-2 onto the dock next: " + c);
    }

    @Test
    void aModelsMoveIntoTheLobbyEndsAtAFreeSpotAndOneOutOfItStartsWhereTheCourierParked() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        traffic.place("courier-1", LobbyParking.DOCK);
        traffic.place("courier-2", "lobby.1");
        traffic.place("courier-3", "c4");
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        assertEquals(List.of("lobby.1", "lobby", "c4"), lobby.route("courier-2", "lobby.1", "lobby", "c4"));
        assertEquals(List.of("c5", "c6"), lobby.route("courier-2", "c5", "c5", "c6"), "away from the lobby nothing changes");
        List<String> in = lobby.route("courier-3", "c4", "c4", "lobby");
        assertEquals(List.of("c4", "lobby"), in.subList(0, 2));
        String spot = in.get(2);
        assertTrue(LobbyParking.spots().contains(spot), in.toString());
        assertFalse(List.of("lobby.1", LobbyParking.DOCK).contains(spot), "not where another courier parked: " + in);
        // the second time it parks, its own spot again; another courier does not get it
        assertEquals(spot, lobby.freeSpot("courier-3").orElseThrow());
        assertFalse(lobby.freeSpot("courier-4").orElseThrow().equals(spot));
        // the models' edge carries the action; the parking lanes are plain drives
        List<RemoteAgv.EdgeAction> actions = LobbyRoutes.actions(List.of("lobby.1", "lobby", "c4"), "lobby", "c4",
                new RemoteAgv.EdgeAction("guide", java.util.Map.of("personId", "alice")));
        assertEquals(null, actions.get(0));
        assertEquals("guide", actions.get(1).actionType());
        assertEquals(List.of("lobby.1", "lobby", LobbyParking.DOCK), lobby.toDock("lobby.1"));
        assertEquals(List.of(), lobby.toDock(LobbyParking.DOCK));
    }

    @Test
    void aCourierLeftOnTheRingParksInTheLobbyByTheFewestEdgesAndNeverThroughTheLift() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        traffic.place("courier-1", "c1");
        traffic.place("courier-2", "c7");
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        List<String> fromC1 = lobby.toParking("courier-1", "c1");
        assertEquals(List.of("c1", "c4", "lobby"), fromC1.subList(0, 3));
        assertTrue(LobbyParking.spots().contains(fromC1.get(3)), fromC1.toString());
        List<String> fromC7 = lobby.toParking("courier-2", "c7");
        assertEquals(List.of("c7", "c6", "c5", "c4", "lobby"), fromC7.subList(0, 5), "along the south corridor, not up the lift");
        assertFalse(fromC7.get(5).equals(fromC1.get(3)), "each its own spot");
    }

    @Test
    void onlyACourierIdleOnTheRingIsSentOutOfTheWay() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        traffic.place("courier-1", "c5");
        traffic.place("courier-2", "ward3");
        traffic.place("courier-3", "lobby.2");
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        List<String> fromC5 = lobby.outOfTheWay("courier-1", "c5");
        assertEquals(List.of("c5", "c4", "lobby"), fromC5.subList(0, 3));
        assertTrue(LobbyParking.spots().contains(fromC5.get(3)) && !fromC5.get(3).equals("lobby.2"), fromC5.toString());
        assertEquals(List.of(), lobby.outOfTheWay("courier-2", "ward3"), "a room is out of the way");
        assertEquals(List.of(), lobby.outOfTheWay("courier-3", "lobby.2"), "parked already");
        assertEquals(List.of(), lobby.outOfTheWay("courier-1", null), "no state yet");
        traffic.place("courier-4", LobbyParking.DOCK);
        List<String> offTheDock = lobby.outOfTheWay("courier-4", LobbyParking.DOCK);
        assertEquals(List.of(LobbyParking.DOCK, LobbyParking.HALL), offTheDock.subList(0, 2), "off the dock, free for the next");
        assertTrue(LobbyParking.spots().contains(offTheDock.get(2)), offTheDock.toString());
    }

    @Test
    void nobodyIsSentOutOfTheWayOntoASpotBetweenTwoParkedCouriers() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        List<String> spots = new ArrayList<>(LobbyParking.spots());
        spots.remove("lobby.1"); // between lobby.2 and lobby.14, 0.95 and 0.75 m off
        for (int i = 0; i < spots.size(); i++) {
            traffic.place("courier-" + i, spots.get(i));
        }
        traffic.place("courier-99", "c5");
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        assertEquals(Optional.of("lobby.1"), lobby.freeSpot("courier-99"));
        assertEquals(Optional.empty(), lobby.spotApart("courier-99"));
        assertEquals(List.of(), lobby.outOfTheWay("courier-99", "c5"), "it would stop short of lobby.1 and stand in the hall");
    }

    @Test
    void nobodyParksOnOrBesideASpotAnotherCourierWaitsOnTheWayTo() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        traffic.place("courier-1", "c4");
        traffic.place("courier-2", "c1");
        LobbyRoutes lobby = LobbyRoutes.of(traffic);
        List<String> park = lobby.outOfTheWay("courier-2", "c1");
        String spot = park.get(park.size() - 1);
        // courier-2 waits at c1 for c4, held by courier-1, on its way to the spot
        assertInstanceOf(Decision.Waiting.class, traffic.read(t -> t.request("courier-2", park)));
        String other = lobby.freeSpot("courier-3").orElseThrow();
        assertFalse(other.equals(spot) || LobbyParking.besideTaken(other, spot::equals), other + " is " + spot + " or beside it");
    }

    @Test
    void aCourierArrivingParksOnASpotWithNobodyBesideIt() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        traffic.place("courier-1", "lobby.1");
        String spot = LobbyRoutes.of(traffic).freeSpot("courier-2").orElseThrow();
        assertFalse(LobbyParking.besideTaken(spot, "lobby.1"::equals), spot + " is beside courier-1's lobby.1");
    }

    @Test
    void whenEverySpotIsTakenAMoveIntoTheLobbyEndsInTheHall() {
        TrafficControl traffic = new TrafficControl(MAP, 120, line -> { });
        List<String> spots = new ArrayList<>(LobbyParking.spots());
        for (int i = 0; i < spots.size(); i++) {
            traffic.place("courier-" + i, spots.get(i));
        }
        assertEquals(Optional.empty(), LobbyRoutes.of(traffic).freeSpot("courier-99"));
        assertEquals(List.of(), LobbyRoutes.of(traffic).toParking("courier-99", "c4"), "nowhere to park");
        assertEquals(List.of("c4", "lobby"), LobbyRoutes.of(traffic).route("courier-99", "c4", "c4", "lobby"));
    }

    /**
     * Every lane of the map has the metres a courier drives on it (the models' distances, the ride into the cabin and out),
     * so that a courier's reserve for the dock is measured on the map: from the upper floor's far ward, 45.5 m back to the
     * dock, through the lift.
     */
    @Test
    void everyLaneHasItsMetresAndTheWayBackToTheDockIsMeasuredOnThem() {
        HospitalFloor floor = new HospitalFloor();
        for (String a : MAP.nodeIds()) {
            for (String b : MAP.neighbours(a)) {
                assertEquals(org.triad.examples.hospital.SimulatedBuilding.routeLength(floor, a, b), MAP.length(a, b).orElseThrow(), 1e-9, a + "-" + b);
            }
        }
        org.triad.building.ChargeReserve reserve = new org.triad.building.ChargeReserve(MAP, LobbyParking.DOCK,
                org.triad.examples.hospital.HospitalObjects.DRAIN_PERCENT_PER_METRE, 10, null);
        assertEquals(List.of("ward5", "d2", "d1", "c7", "c6", "c5", "c4", "lobby", LobbyParking.DOCK), reserve.wayToDock("ward5"));
        assertEquals(45.5, reserve.metres(reserve.wayToDock("ward5")), 0.1);
        assertEquals(45.5 * 0.5 + 10, reserve.reserveAt("ward5"), 0.1);
    }
}
