package org.triad.building.traffic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import org.triad.building.traffic.Resource.Kind;

class TrafficMapTest {

    @Test
    void aStepOccupiesTheEdgeTheNodeAheadAndTheAreasAroundThem() {
        TrafficMap map = Maps.singleLane(2);
        assertEquals(Set.of(map.edge("hall-w", "c1").orElseThrow(), map.node("c1"), map.area("west").orElseThrow()), map.step("hall-w", "c1"));
        assertEquals(map.edge("c1", "c2"), map.edge("c2", "c1"), "an edge is one lane both ways");
        assertTrue(map.isStop("hall-w"));
        assertFalse(map.isStop("c1"), "a robot never waits inside a corridor");
        assertEquals(Set.of(map.node("hall-e")), map.standing("hall-e"));
    }

    @Test
    void aZoneAdmitsRobotsToARegionButAHallInItIsStillAStop() {
        TrafficMap map = TrafficMap.builder().node("hall", 2).node("ward").edge("hall", "ward").area(Kind.ZONE, "floor1", 1, "hall", "ward", "hall-ward")
                .build();
        assertTrue(map.isStop("hall"), "a robot may wait in a hall of its floor");
        assertEquals(Set.of(map.node("hall"), map.area("floor1").orElseThrow()), map.standing("hall"), "standing on the floor holds its zone");
    }

    @Test
    void anEdgeWhoseNodeDoesNotExistIsAClearError() {
        TrafficMapException e = assertThrows(TrafficMapException.class,
                () -> TrafficMap.builder().node("a").edge("a", "b").build());
        assertEquals(List.of("edge 'a-b' joins node 'b', which is not on the map"), e.problems());
    }

    @Test
    void aCapacityOfZeroIsAClearErrorForNodesEdgesAndAreas() {
        TrafficMapException e = assertThrows(TrafficMapException.class, () -> TrafficMap.builder().node("a", 0).node("b")
                .edge("ab", "a", "b", 0).area(Kind.LIFT, "lift", 0, "a").build());
        assertEquals(List.of("node 'a' has capacity 0; a capacity is at least 1 robot", "edge 'ab' has capacity 0; a capacity is at least 1 robot",
                "lift 'lift' has capacity 0; a capacity is at least 1 robot"), e.problems());
        assertTrue(e.getMessage().startsWith("bad traffic map: node 'a' has capacity 0"), e.getMessage());
    }

    @Test
    void everyOtherProblemIsNamedTooAllAtOnce() {
        TrafficMapException e = assertThrows(TrafficMapException.class, () -> TrafficMap.builder().node("a").node("a").node("b")
                .edge("a", "a").edge("a", "b").edge("x", "b", "a", 1).area(Kind.DOOR, "d", 1, "a", "nowhere").area(Kind.CORRIDOR, "empty", 1)
                .area(Kind.NODE, "odd", 1, "b").build());
        assertEquals(List.of("node 'a' is declared twice (or an edge has that id)", "edge 'a-a' joins node 'a' to itself",
                "edge 'x' joins nodes 'b' and 'a', already joined by another edge", "corridor 'empty' covers no node or edge",
                "area 'odd' has kind NODE; an area is a corridor, door, lift or zone",
                "door 'd' covers 'nowhere', which is neither a node nor an edge of the map"), e.problems());
        assertThrows(TrafficMapException.class, () -> TrafficMap.builder().build(), "a map without nodes");
    }

    @Test
    void askingForWhatIsNotOnTheMapIsAClearError() {
        TrafficMap map = Maps.singleLane(2);
        assertEquals("node 'zz' is not on the traffic map", assertThrows(IllegalArgumentException.class, () -> map.node("zz")).getMessage());
        assertEquals("no edge joins node 'hall-w' and node 'hall-e' on the traffic map",
                assertThrows(IllegalArgumentException.class, () -> map.step("hall-w", "hall-e")).getMessage());
    }

    @Test
    void anEdgeHasTheLengthTheFloorMapGaveItEitherWayRoundAndABadLengthIsAClearError() {
        TrafficMap map = TrafficMap.builder().node("a").node("b").node("c").edge("a", "b").edge("b", "c").length("a-b", 4.5).build();
        assertEquals(4.5, map.length("a", "b").orElseThrow());
        assertEquals(4.5, map.length("b", "a").orElseThrow(), "one lane both ways");
        assertTrue(map.length("b", "c").isEmpty(), "not given");
        assertThrows(IllegalArgumentException.class, () -> map.length("a", "c"));
        TrafficMapException e = assertThrows(TrafficMapException.class, () -> TrafficMap.builder().node("a").node("b").edge("a", "b")
                .length("a-b", -1).length("b-a", 2).build());
        assertEquals(List.of("edge 'a-b' has length -1.0; a length is a finite number of metres >= 0",
                "a length is given for edge 'b-a', which is not an edge of the map"), e.problems());
    }
}
