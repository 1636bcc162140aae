package org.triad.building;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import org.triad.building.traffic.TrafficMap;

class ChargeReserveTest {
    /**
     * dock - hall - a - b - far, and a short cut hall - b that is longer in metres than hall - a - b:
     * dock 2 m, hall-a 8 m, a-b 8 m, b-far 20 m, hall-b 30 m.
     */
    private static TrafficMap map() {
        return TrafficMap.builder().node("dock").node("hall").node("a").node("b").node("far")
                .edge("dock", "hall").edge("hall", "a").edge("a", "b").edge("b", "far").edge("hall", "b")
                .length("dock-hall", 2).length("hall-a", 8).length("a-b", 8).length("b-far", 20).length("hall-b", 30).build();
    }

    @Test
    void aLegIsTakenOnlyIfTheChargeCoversItTheWayBackToTheDockAndTheMargin() {
        ChargeReserve r = new ChargeReserve(map(), "dock", 0.5, 10, null);
        // the leg a -> b -> far is 28 m (14 %), far's way back far - b - a - hall - dock is 38 m (19 %), and 10 % margin
        assertEquals(List.of("far", "b", "a", "hall", "dock"), r.wayToDock("far"), "the shortest by metres, not by edges");
        assertEquals(43.0, r.needed(List.of("a", "b", "far")), 1e-9);
        assertTrue(r.covers(43.0, List.of("a", "b", "far")));
        assertFalse(r.covers(42.9, List.of("a", "b", "far")), "below: to the dock first");
        // the same charge takes a shorter leg that ends nearer the dock
        assertEquals(8 * 0.5 + 2 * 0.5 + 10, r.needed(List.of("a", "hall")), 1e-9);
        assertTrue(r.covers(42.9, List.of("a", "hall")));
        assertEquals(10.0, r.reserveAt("dock"), 1e-9, "at the dock, the margin only");
        assertEquals(19 + 10.0, r.reserveAt("far"), 1e-9);
        assertEquals("43.0 % needed: 28.0 m of the leg, 38.0 m back to dock, 10 % margin", r.explain(List.of("a", "b", "far")));
    }

    @Test
    void theWayBackIsTheRouteTheRobotDrivesWhenTheCallerSaysWhichThatIs() {
        // a robot routed by fewest edges goes back far - b - hall - dock: 52 m, not 38
        ChargeReserve r = new ChargeReserve(map(), "dock", 0.5, 10, (from, to) -> from.equals("far") ? List.of("far", "b", "hall", "dock") : List.of(from, to));
        assertEquals(52 * 0.5 + 10, r.reserveAt("far"), 1e-9);
    }

    @Test
    void aMapWithoutLengthsOrABadDrainIsAClearError() {
        TrafficMap unmeasured = TrafficMap.builder().node("dock").node("hall").edge("dock", "hall").build();
        assertEquals("the traffic map gives no length for the edge between 'dock' and 'hall': a charge's reserve is measured on the map's lanes",
                assertThrows(IllegalArgumentException.class, () -> new ChargeReserve(unmeasured, "dock", 0.5, 10, null)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new ChargeReserve(map(), "dock", 0, 10, null));
        assertThrows(IllegalArgumentException.class, () -> new ChargeReserve(map(), "dock", 0.5, -1, null));
        assertEquals("node 'nowhere' is not on the traffic map",
                assertThrows(IllegalArgumentException.class, () -> new ChargeReserve(map(), "nowhere", 0.5, 10, null)).getMessage());
    }
}
