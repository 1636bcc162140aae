package org.triad.building.traffic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Decision.Waiting;
import org.triad.building.traffic.ReservationTable.Changes;
import org.triad.building.traffic.Resource.Kind;

class ReservationTableTest {
    private final double[] now = { 0 };

    private ReservationTable table(TrafficMap map) {
        return new ReservationTable(map, () -> now[0]);
    }

    private static List<String> route(String... nodes) {
        return List.of(nodes);
    }

    /** Drives the robot along its whole base, node by node, collecting what that set free. */
    private static Changes driveBase(ReservationTable t, String robot) {
        Changes all = Changes.NONE;
        for (String n : List.copyOf(t.base(robot)).subList(1, t.base(robot).size())) {
            all = all.merge(t.passed(robot, n));
        }
        return all;
    }

    @Test
    void headToHeadOnASingleLaneTheSecondWaitsAtTheHallAndGoesWhenTheFirstIsThrough() {
        TrafficMap map = Maps.singleLane(3);
        ReservationTable t = table(map);
        t.place("r1", "hall-w");
        t.place("r2", "hall-e");
        Granted g1 = assertInstanceOf(Granted.class, t.request("r1", route("hall-w", "c1", "c2", "hall-e", "side-e")));
        assertEquals(route("hall-w", "c1", "c2", "hall-e"), g1.stretch(), "the whole corridor at once, up to the next hall");
        assertEquals(route("hall-e", "side-e"), g1.horizon());
        Waiting w2 = assertInstanceOf(Waiting.class, t.request("r2", route("hall-e", "c2", "c1", "hall-w")));
        assertEquals(List.of(map.area("west").orElseThrow(), map.edge("c2", "hall-e").orElseThrow(), map.node("c2"),
                map.edge("c1", "c2").orElseThrow(), map.node("c1"), map.edge("hall-w", "c1").orElseThrow()).stream().sorted(
                        java.util.Comparator.comparing(Resource::toString)).toList(),
                w2.queued().blocking().stream().sorted(java.util.Comparator.comparing(Resource::toString)).toList());
        assertEquals(List.of("r1"), w2.queued().blockers());
        assertTrue(w2.queued().reason().startsWith("r2 waits at hall-e for "), w2.queued().reason());
        assertFalse(t.released("r2", "c2"), "a waiting robot may not drive into the corridor");

        now[0] = 12;
        assertTrue(t.passed("r1", "c1").isEmpty());
        assertTrue(t.passed("r1", "c2").isEmpty(), "the corridor is held until r1 is out of it");
        Changes out = t.passed("r1", "hall-e");
        assertEquals(List.of("r2"), out.granted().stream().map(Granted::robot).toList());
        assertEquals(route("hall-e", "c2", "c1", "hall-w"), t.base("r2"));
        assertEquals(Set.of("r2"), t.holders(map.area("west").orElseThrow()));
        assertEquals(List.of(12.0), t.stats().waits(Kind.CORRIDOR));
        driveBase(t, "r2");
        assertEquals(route("hall-w"), t.base("r2"));
        assertTrue(t.holders(map.area("west").orElseThrow()).isEmpty());
    }

    @Test
    void aRobotDoesNotFillAHallOnItsWayThroughItReservesThroughItToTheNextStop() {
        TrafficMap map = Maps.singleLane(2);
        ReservationTable t = table(map);
        t.place("r1", "hall-w");
        t.place("r2", "hall-e");
        Granted g1 = assertInstanceOf(Granted.class, t.request("r1", route("hall-w", "c1", "c2", "hall-e", "side-e")));
        assertEquals(route("hall-w", "c1", "c2", "hall-e", "side-e"), g1.stretch(),
                "with r2 in hall-e, r1 waiting there too would leave no room to pass: through it to side-e at once");
        driveBase(t, "r1");
        assertEquals(Set.of("r2"), t.holders(map.node("hall-e")), "r1 drove through hall-e without stopping");
        t.place("r3", "side-w");
        Granted g3 = assertInstanceOf(Granted.class, t.request("r3", route("side-w", "hall-w", "c1", "c2", "hall-e")));
        assertEquals(route("side-w", "hall-w"), g3.stretch(), "an empty hall-w keeps room after r3: r3 may stop there");
    }

    @Test
    void aRobotDoesNotWaitAtTheDoorOfATakenDeadEndItReservesTheDoorAndTheRoomTogether() {
        // w - m - e, and a room off m (a dead end: its only way out is m)
        TrafficMap map = TrafficMap.builder().node("w").node("m").node("e").node("room").edge("w", "m").edge("m", "e").edge("m", "room").build();
        ReservationTable t = table(map);
        t.place("r1", "room");
        t.place("r2", "w");
        assertTrue(t.deadEndTaken("m", "room", "r2"));
        assertFalse(t.deadEndTaken("m", "room", "r1"), "its own room");
        assertFalse(t.deadEndTaken("w", "m", "r2"), "m is no dead end");
        Waiting w2 = assertInstanceOf(Waiting.class, t.request("r2", route("w", "m", "room")));
        assertEquals(route("w", "m", "room"), w2.queued().stretch(), "the door m and the room at once, not m first");
        assertFalse(t.released("r2", "m"), "r2 waits at w: m stays free for r1 to come out");
        // r1 comes out: r2 was queued first for m, but waits for r1, so r1 goes first (rule 3) instead of being refused
        Granted out = assertInstanceOf(Granted.class, t.request("r1", route("room", "m", "e")));
        assertEquals(route("room", "m"), out.stretch());
        driveBase(t, "r1");
        assertInstanceOf(Granted.class, t.request("r1", route("m", "e")));
        Changes c = driveBase(t, "r1");
        assertEquals(List.of("r2"), c.granted().stream().map(Granted::robot).toList());
        assertEquals(route("w", "m", "room"), t.base("r2"));
        // with the room free, a robot stops at its door as before
        driveBase(t, "r2");
        assertInstanceOf(Granted.class, t.request("r2", route("room", "m", "w")));
        driveBase(t, "r2");
        assertInstanceOf(Granted.class, t.request("r2", route("m", "w")));
        driveBase(t, "r2");
        Granted g1 = assertInstanceOf(Granted.class, t.request("r1", route("e", "m", "room")));
        assertEquals(route("e", "m"), g1.stretch());
    }

    /**
     * The service's benchmark jammed on this (courier-4 at c1, courier-3 in the storage room, for the whole run): a robot
     * standing at the door of a dead end waits to go in, and the robot inside asks to come out. Refusing the one inside,
     * as rule 3 did, left both where they were: it has no other way out. The one at the door is refused instead.
     */
    @Test
    void aRobotComingOutOfADeadEndIsQueuedAndTheOneWaitingAtItsDoorIsRefusedToMakeWay() {
        TrafficMap map = TrafficMap.builder().node("w").node("m").node("e").node("room").edge("w", "m").edge("m", "e").edge("m", "room").build();
        ReservationTable t = table(map);
        t.place("r1", "room");
        t.place("r2", "m"); // its last route ended at the door
        assertInstanceOf(Waiting.class, t.request("r2", route("m", "room")));
        assertEquals(List.of(), t.takeDisplaced());
        Waiting out = assertInstanceOf(Waiting.class, t.request("r1", route("room", "m", "e")), "not refused: it waits for r2 to go");
        assertEquals(List.of("r2"), out.queued().blockers());
        List<Refused> displaced = t.takeDisplaced();
        assertEquals(1, displaced.size());
        assertEquals("r2", displaced.get(0).robot());
        assertEquals(List.of("r2", "r1"), displaced.get(0).cycle());
        assertTrue(displaced.get(0).reason().contains("r2 makes way"), displaced.get(0).reason());
        assertTrue(t.waiting("r2").isEmpty(), "r2's wait for the room is withdrawn");
        assertTrue(t.takeDisplaced().isEmpty(), "told once");
        // r2 steps aside to w; the door is free and r1 comes out
        assertInstanceOf(Granted.class, t.request("r2", route("m", "w")));
        Changes c = driveBase(t, "r2");
        assertEquals(List.of("r1"), c.granted().stream().map(Granted::robot).toList());
        assertEquals(route("room", "m"), t.base("r1"));
        assertEquals(java.util.Map.of(), t.waitsFor());
    }

    @Test
    void headToHeadBetweenNodesForOneRobotIsRefusedAsADeadlockAndResolvedByYieldingToASideNode() {
        ReservationTable t = table(Maps.singleLane(1));
        t.place("r1", "hall-w");
        t.place("r2", "hall-e");
        assertInstanceOf(Waiting.class, t.request("r1", route("hall-w", "c1", "c2", "hall-e", "side-e")));
        Refused r = assertInstanceOf(Refused.class, t.request("r2", route("hall-e", "c2", "c1", "hall-w", "side-w")));
        assertEquals("deadlock avoided: r2 would wait for r1 (node 'hall-w'), r1 would wait for r2 (node 'hall-e'); r2 does not wait at hall-e",
                r.reason());
        assertTrue(t.waiting("r2").isEmpty());
        // r2 yields to its side room; the hall it leaves lets r1 through
        assertInstanceOf(Granted.class, t.request("r2", route("hall-e", "side-e")));
        Changes c = t.passed("r2", "side-e");
        assertEquals(List.of("r1"), c.granted().stream().map(Granted::robot).toList());
        assertEquals(route("hall-w", "c1", "c2", "hall-e"), t.base("r1"));
    }

    @Test
    void threeRobotsInARingOfThreeCorridorsNeverWaitInACycle() {
        ReservationTable t = table(Maps.ring(1));
        t.place("r1", "n1");
        t.place("r2", "n2");
        t.place("r3", "n3");
        assertInstanceOf(Waiting.class, t.request("r1", route("n1", "m12", "n2")));
        assertInstanceOf(Waiting.class, t.request("r2", route("n2", "m23", "n3")));
        Refused r = assertInstanceOf(Refused.class, t.request("r3", route("n3", "m31", "n1")));
        assertTrue(r.reason().startsWith("deadlock avoided: r3 would wait for r1 (node 'n1'), r1 would wait for r2 (node 'n2'), r2 would wait for r3"),
                r.reason());
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()));
    }

    @Test
    void threeRobotsInARingWithHallsForThreeAllGoRoundTwice() {
        ReservationTable t = table(Maps.ring(3));
        List<String> ring = route("n1", "m12", "n2", "m23", "n3", "m31", "n1", "m12", "n2", "m23", "n3", "m31", "n1");
        String[] robots = { "r1", "r2", "r3" };
        for (int i = 0; i < 3; i++) {
            t.place(robots[i], ring.get(2 * i));
        }
        int[] at = new int[3];
        int moves = 0;
        while (moves < 1000 && (at[0] < 12 || at[1] < 12 || at[2] < 12)) {
            for (int i = 0; i < 3; i++) {
                String r = robots[i];
                if (t.base(r).size() > 1) {
                    t.passed(r, t.base(r).get(1));
                    at[i]++;
                    moves++;
                } else if (at[i] < 12 && t.waiting(r).isEmpty()) {
                    List<String> route = rotated(ring, 2 * i).subList(at[i], 13);
                    Decision d = t.request(r, route);
                    assertFalse(d instanceof Refused, d.toString());
                }
            }
        }
        assertEquals(List.of(12, 12, 12), List.of(at[0], at[1], at[2]), "every robot went round twice");
    }

    private static List<String> rotated(List<String> ring, int by) {
        List<String> loop = ring.subList(0, 6);
        List<String> r = new java.util.ArrayList<>();
        for (int i = 0; i <= 12; i++) {
            r.add(loop.get((i + by) % 6));
        }
        return r;
    }

    @Test
    void twoRobotsForTheLiftOneRidesTheNextWaitsAndRidesNextInOrder() {
        TrafficMap map = Maps.lift();
        Resource lift = map.area("lift").orElseThrow();
        ReservationTable t = table(map);
        t.place("r1", "f1");
        t.place("r2", "f1");
        t.place("r3", "f1");
        List<String> up = route("f1", "lift-1", "lift-2", "f2");
        assertEquals(up, assertInstanceOf(Granted.class, t.request("r1", up)).stretch(), "the whole ride at once: nobody waits in the cabin");
        Waiting w2 = assertInstanceOf(Waiting.class, t.request("r2", up));
        assertTrue(w2.queued().reason().contains("lift 'lift'"), w2.queued().reason());
        Waiting w3 = assertInstanceOf(Waiting.class, t.request("r3", up));
        assertEquals(List.of("r1", "r2"), w3.queued().blockers(), "r3 queues behind r2");
        assertEquals(Set.of("r1"), t.holders(lift));
        assertTrue(t.passed("r1", "lift-1").isEmpty());
        assertTrue(t.passed("r1", "lift-2").isEmpty());
        assertEquals(List.of("r2"), t.passed("r1", "f2").granted().stream().map(Granted::robot).toList(), "the lift goes to the first in line");
        assertEquals(Set.of("r2"), t.holders(lift));
        assertEquals(List.of("r3"), driveBase(t, "r2").granted().stream().map(Granted::robot).toList());
        driveBase(t, "r3");
        assertEquals(List.of("f2", "f2", "f2"), List.of(t.base("r1").get(0), t.base("r2").get(0), t.base("r3").get(0)));
    }

    @Test
    void aRobotTheQueuedOnesWaitForGoesFirstInsteadOfBeingRefused() {
        TrafficMap map = Maps.lift();
        ReservationTable t = table(map);
        t.place("down", "f2");
        t.place("x1", "f2");
        t.place("x2", "f2");
        t.place("up", "f1");
        Waiting w = assertInstanceOf(Waiting.class, t.request("up", route("f1", "lift-1", "lift-2", "f2")));
        assertTrue(w.queued().blockers().contains("down"), "f2 is full: up waits for the robots standing there");
        // down queuing behind up for the lift would close a cycle (up waits for down's place in f2): it rides first
        Granted g = assertInstanceOf(Granted.class, t.request("down", route("f2", "lift-2", "lift-1", "f1")));
        assertEquals(route("f2", "lift-2", "lift-1", "f1"), g.stretch());
        assertEquals(List.of("up"), driveBase(t, "down").granted().stream().map(Granted::robot).toList(), "then up rides into the place down left");
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()));
    }

    @Test
    void aLaterRequestDoesNotOvertakeAnEarlierOneForTheSameResourceButMayUseSpareCapacity() {
        TrafficMap map = TrafficMap.builder().node("a", 3).node("b").node("c", 3).edge("ab", "a", "b", 3).edge("bc", "b", "c", 3)
                .area(Kind.DOOR, "door", 1, "b").build();
        ReservationTable t = table(map);
        t.place("r1", "a");
        t.place("r2", "a");
        t.place("r3", "c");
        assertInstanceOf(Granted.class, t.request("r1", route("a", "b", "c")));
        assertInstanceOf(Waiting.class, t.request("r2", route("a", "b", "c")));
        Waiting w3 = assertInstanceOf(Waiting.class, t.request("r3", route("c", "b", "a")));
        assertEquals(List.of("r1", "r2"), w3.queued().blockers());
        driveBase(t, "r1");
        assertEquals(route("a", "b", "c"), t.base("r2"));
        assertTrue(t.waiting("r3").isPresent());
    }

    @Test
    void aRobotLostInTheCorridorKeepsItsPlaceOthersAreRefusedWithTheReasonAndGoOnWhenItIsTakenAway() {
        TrafficMap map = Maps.singleLane(3);
        Resource corridor = map.area("west").orElseThrow();
        ReservationTable t = table(map);
        t.place("r1", "hall-w");
        t.place("r2", "hall-e");
        t.place("r3", "hall-e");
        t.request("r1", route("hall-w", "c1", "c2", "hall-e"));
        t.passed("r1", "c1");
        assertInstanceOf(Waiting.class, t.request("r2", route("hall-e", "c2", "c1", "hall-w")));
        Changes c = t.lost("r1", "CONNECTIONBROKEN (its last will)");
        assertEquals(List.of("r2"), c.refused().stream().map(Refused::robot).toList());
        assertEquals("corridor 'west' is blocked by robot r1, lost there (CONNECTIONBROKEN (its last will))", c.refused().get(0).reason());
        assertFalse(t.holders(map.node("hall-e")).contains("r1"), "its base ahead is freed");
        assertEquals(Set.of("r1"), t.holders(corridor), "nobody is sent into it");
        assertInstanceOf(Refused.class, t.request("r2", route("hall-e", "c2", "c1", "hall-w")));
        assertInstanceOf(Granted.class, t.request("r3", route("hall-e", "side-e")), "the others continue");
        assertThrows(IllegalStateException.class, () -> t.request("r1", route("c1", "c2")));
        t.remove("r1");
        assertInstanceOf(Granted.class, t.request("r2", route("hall-e", "c2", "c1", "hall-w")));
    }

    @Test
    void anObstacleBlocksAResourceUntilCleared() {
        TrafficMap map = Maps.lift();
        Resource lift = map.area("lift").orElseThrow();
        ReservationTable t = table(map);
        t.place("r1", "f1");
        t.place("r2", "f1");
        t.request("r1", route("f1", "lift-1", "lift-2", "f2"));
        t.request("r2", route("f1", "lift-1", "lift-2", "f2"));
        Changes c = t.block(lift, "the lift did not arrive within 60 s");
        assertEquals("lift 'lift' is blocked: the lift did not arrive within 60 s", c.refused().get(0).reason());
        assertEquals(Double.POSITIVE_INFINITY, t.expectedWait("f1", "lift-1"));
        t.unblock(lift);
        assertInstanceOf(Waiting.class, t.request("r2", route("f1", "lift-1", "lift-2", "f2")));
    }

    @Test
    void aWaitLongerThanTheBoundIsReportedWithItsReasonAndCanBeWithdrawn() {
        ReservationTable t = table(Maps.singleLane(2));
        t.place("r1", "hall-w");
        t.place("r2", "hall-e");
        t.request("r1", route("hall-w", "c1", "c2", "hall-e"));
        now[0] = 5;
        t.request("r2", route("hall-e", "c2", "c1", "hall-w"));
        now[0] = 60;
        assertEquals(List.of(), t.overdue(60));
        now[0] = 66;
        List<Wait> late = t.overdue(60);
        assertEquals(List.of("r2"), late.stream().map(Wait::robot).toList());
        assertEquals(61.0, late.get(0).waited(now[0]));
        assertTrue(late.get(0).reason().contains("corridor 'west'") && late.get(0).reason().contains("r1"), late.get(0).reason());
        t.cancel("r2");
        assertEquals(List.of(), t.waits());
    }

    @Test
    void aCancelledOrderStopsTheRobotAtANodeOfItsBaseAndFreesTheRest() {
        TrafficMap map = Maps.singleLane(2);
        ReservationTable t = table(map);
        t.place("r1", "hall-w");
        t.request("r1", route("hall-w", "c1", "c2", "hall-e"));
        t.passed("r1", "c1");
        t.truncate("r1", "c2");
        assertEquals(route("c1", "c2"), t.base("r1"));
        assertFalse(t.holders(map.node("hall-e")).contains("r1"));
        assertTrue(t.released("r1", "c2"));
        assertFalse(t.released("r1", "hall-e"), "beyond the base: a robot reporting it is a rogue");
        assertThrows(IllegalStateException.class, () -> t.passed("r1", "hall-e"));
    }

    @Test
    void theExpectedWaitOfAStepGrowsWithTheQueue() {
        TrafficMap map = Maps.lift();
        ReservationTable t = table(map);
        for (String r : List.of("r1", "r2", "r3")) {
            t.place(r, "f1");
        }
        List<String> up = route("f1", "lift-1", "lift-2", "f2");
        t.request("r1", up);
        now[0] = 30;
        driveBase(t, "r1"); // the lift was held 30 s
        assertEquals(0.0, t.expectedWait("f1", "lift-1"), "free: no wait");
        t.request("r2", up);
        assertEquals(30.0, t.expectedWait("f1", "lift-1"));
        t.request("r3", up);
        assertEquals(60.0, t.expectedWait("f1", "lift-1"));
    }

    @Test
    void congestionCostsAreTheExpectedWaitInStepsAndABlockedStepIsDear() {
        TrafficMap map = Maps.singleLane(3);
        ReservationTable t = table(map);
        org.triad.runtime.schema.ActionCosts costs = CongestionCosts.of(map, t::expectedWait, 10);
        java.util.function.Function<String, org.triad.runtime.app.GenericObject> wp = n -> new org.triad.runtime.app.GenericObject(n, "WayPoint", java.util.Map.of());
        org.triad.runtime.app.GroundAction move = new org.triad.runtime.app.GroundAction("Courier", "move", List.of(wp.apply("hall-w"), wp.apply("c1")));
        assertEquals(0, costs.extra(move), "a free lane costs nothing extra");
        t.block(map.area("west").orElseThrow(), "a bed in the corridor");
        assertEquals(CongestionCosts.BLOCKED, costs.extra(move));
        assertEquals(0, costs.extra(new org.triad.runtime.app.GroundAction("Courier", "move", List.of(wp.apply("side-w"), wp.apply("c1")))),
                "not joined on the map: not a move traffic knows");
        assertThrows(IllegalArgumentException.class, () -> CongestionCosts.of(map, t::expectedWait, 0));
    }

    @Test
    void misuseIsAClearError() {
        ReservationTable t = table(Maps.singleLane(1));
        t.place("r1", "hall-w");
        assertEquals("robot r2 cannot be placed at node 'hall-w': node 'hall-w' is full (held by r1)",
                assertThrows(IllegalStateException.class, () -> t.place("r2", "hall-w")).getMessage());
        assertEquals("robot r1's route starts at 'c1' but its decision point is 'hall-w'",
                assertThrows(IllegalArgumentException.class, () -> t.request("r1", route("c1", "c2"))).getMessage());
        assertEquals("no edge joins node 'hall-w' and node 'c2' on the traffic map",
                assertThrows(IllegalArgumentException.class, () -> t.request("r1", route("hall-w", "c2"))).getMessage());
        assertEquals("robot r9 is not on the traffic map (place it first)",
                assertThrows(IllegalStateException.class, () -> t.request("r9", route("hall-w", "c1"))).getMessage());
    }

    /**
     * The service's mixed benchmark: courier-3 guiding Alice from c1 to c4, courier-6 at c4 waiting for c1. Refusing the
     * guide had it step aside without the person, or stand (24 of 107 deadlock refusals were that guide). A guide does
     * not make way: the robot of the cycle that waits and guides nobody is refused instead and steps aside.
     */
    @Test
    void aRobotGuidingAPersonDoesNotMakeWayTheOtherRobotOfTheCycleIsRefusedInstead() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c1").node("c4").node("c5")
                .edge("c0", "c1").edge("c1", "c4").edge("c4", "c5").build();
        ReservationTable plain = table(map);
        plain.place("guide", "c1");
        plain.place("other", "c4");
        assertInstanceOf(Waiting.class, plain.request("other", route("c4", "c1", "c0")));
        assertInstanceOf(Refused.class, plain.request("guide", route("c1", "c4", "c5")), "a plain drive is refused as before");

        ReservationTable t = table(map);
        t.place("guide", "c1");
        t.place("other", "c4");
        assertInstanceOf(Waiting.class, t.request("other", route("c4", "c1", "c0")));
        assertInstanceOf(Waiting.class, t.request("guide", route("c1", "c4", "c5"), true), "the guide queues for c4");
        List<Refused> displaced = t.takeDisplaced();
        assertEquals(1, displaced.size());
        assertEquals("other", displaced.get(0).robot());
        assertEquals(List.of("other", "guide"), displaced.get(0).cycle());
        assertTrue(displaced.get(0).reason().contains("other makes way"), displaced.get(0).reason());
        assertTrue(t.waiting("other").isEmpty(), "its wait is withdrawn");
        assertTrue(t.waitsFor().values().stream().noneMatch(w -> w.contains("guide")), "no wait-for cycle is left");

        // the other steps aside to c5 (granted: the guide waits for c4 only), and the guide goes
        assertInstanceOf(Granted.class, t.request("other", route("c4", "c5")));
        Changes c = driveBase(t, "other");
        assertEquals(List.of("guide"), c.granted().stream().map(Granted::robot).toList());
    }

    @Test
    void twoGuidesInACycleAreRefusedAsBefore() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c1").node("c4").node("c5")
                .edge("c0", "c1").edge("c1", "c4").edge("c4", "c5").build();
        ReservationTable t = table(map);
        t.place("a", "c1");
        t.place("b", "c4");
        assertInstanceOf(Waiting.class, t.request("b", route("c4", "c1", "c0"), true));
        assertInstanceOf(Refused.class, t.request("a", route("c1", "c4", "c5"), true), "nobody in the cycle can make way but the asker");
        assertTrue(t.takeDisplaced().isEmpty());
        assertTrue(t.waiting("b").isPresent());
    }

    /** c4 - c5 - c6 - c7, one lane, and ward2 off c6: the east side of the hospital's upper floor, where courier-3 starved. */
    private static TrafficMap eastSide() {
        return TrafficMap.builder().node("c4").node("c5").node("c6").node("c7").node("ward2")
                .edge("c4", "c5").edge("c5", "c6").edge("c6", "c7").edge("c6", "ward2").build();
    }

    /**
     * The building benchmark's starvation: courier-3, on its way to the dock, refused at c6 as a deadlock head to head
     * again and again, against one courier after another, stepping aside to ward2 each time, until its battery was
     * empty. Rule 3 refused whoever closed the cycle. Now the robot refused before has precedence: the next robot it
     * meets head to head, refused fewer times, makes way instead. A step aside (a grant too) does not spend it; getting
     * through the step it was refused does.
     */
    @Test
    void aRobotRefusedBeforeWinsTheNextCycleHeadToHeadAndTheOtherIsDisplaced() {
        ReservationTable t = table(eastSide());
        t.place("r3", "c6");
        t.place("r2", "c5");
        assertInstanceOf(Waiting.class, t.request("r2", route("c5", "c6", "c7")));
        Refused first = assertInstanceOf(Refused.class, t.request("r3", route("c6", "c5", "c4")), "tied at 0: the asker is refused as before");
        assertEquals(List.of("r3", "r2"), first.cycle());
        assertEquals(1, t.refusals("r3"));
        assertEquals(0, t.refusals("r2"));
        assertTrue(t.takeDisplaced().isEmpty());

        // r3 steps aside to ward2; r2 passes on to c7
        assertInstanceOf(Granted.class, t.request("r3", route("c6", "ward2")));
        assertEquals(List.of("r2"), driveBase(t, "r3").granted().stream().map(Granted::robot).toList());
        driveBase(t, "r2");
        assertInstanceOf(Granted.class, t.request("r2", route("c6", "c7")));
        driveBase(t, "r2");
        assertEquals(1, t.refusals("r3"), "a step aside is a grant, but not through where it was refused");

        // back to c6, and r4 comes up the lane from c4 to c5 and waits for c6: head to head again
        assertInstanceOf(Granted.class, t.request("r3", route("ward2", "c6", "c5", "c4")));
        driveBase(t, "r3");
        assertEquals(1, t.refusals("r3"));
        t.place("r4", "c4");
        assertInstanceOf(Granted.class, t.request("r4", route("c4", "c5", "c6", "c7")));
        driveBase(t, "r4");
        assertInstanceOf(Waiting.class, t.request("r4", route("c5", "c6", "c7")));
        Waiting w3 = assertInstanceOf(Waiting.class, t.request("r3", route("c6", "c5", "c4")), "refused once before, r3 is not refused again");
        assertEquals(List.of("r4"), w3.queued().blockers(), "it waits for r4 to leave c5");
        List<Refused> displaced = t.takeDisplaced();
        assertEquals(1, displaced.size());
        assertEquals("r4", displaced.get(0).robot());
        assertEquals(List.of("r4", "r3"), displaced.get(0).cycle());
        assertTrue(displaced.get(0).reason().contains("r3 was refused 1 times since it last got through, r4 0; r4 makes way"),
                displaced.get(0).reason());
        assertTrue(t.waiting("r4").isEmpty(), "r4's wait is withdrawn");
        assertEquals(1, t.refusals("r4"), "being displaced counts as a refusal");
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()), "no wait-for cycle is left");

        // r4 makes way back to c4 and on (off the lane); r3 gets c5, through where it was refused, and on to c4, the end of
        // its drive: only then its count ends
        assertInstanceOf(Granted.class, t.request("r4", route("c5", "c4")));
        Changes c = driveBase(t, "r4");
        assertEquals(List.of("r3"), c.granted().stream().map(Granted::robot).toList());
        assertEquals(1, t.refusals("r3"), "through c6-c5, not yet at the end of its drive");
        t.remove("r4");
        driveBase(t, "r3");
        assertInstanceOf(Granted.class, t.request("r3", route("c5", "c4")));
        assertEquals(0, t.refusals("r3"));
    }

    /** Equal counts refuse the asker as before, so two robots that stay where they are take turns; a guide is never displaced by age. */
    @Test
    void tiesRefuseTheAskerAndAGuideIsNotDisplacedByAge() {
        ReservationTable t = table(eastSide());
        t.place("a", "c6");
        t.place("b", "c5");
        assertInstanceOf(Waiting.class, t.request("a", route("c6", "c5", "c4")));
        assertInstanceOf(Refused.class, t.request("b", route("c5", "c6", "c7")), "0 against 0: the asker");
        assertInstanceOf(Waiting.class, t.request("b", route("c5", "c6", "c7")), "1 against 0: a makes way");
        assertEquals(List.of("a"), t.takeDisplaced().stream().map(Refused::robot).toList());
        Refused tie = assertInstanceOf(Refused.class, t.request("a", route("c6", "c5", "c4")), "1 against 1: the asker");
        assertEquals(List.of("a", "b"), tie.cycle());
        assertTrue(t.takeDisplaced().isEmpty());
        assertTrue(t.waiting("b").isPresent(), "b keeps its wait");
        assertEquals(2, t.refusals("a"));
        assertEquals(1, t.refusals("b"));
        // master control asks b to make way (a had nowhere to step aside to): withdrawn and counted like the table's own
        assertTrue(t.makeWay("b").isEmpty());
        assertTrue(t.waiting("b").isEmpty());
        assertEquals(2, t.refusals("b"));
        assertTrue(t.makeWay("b").isEmpty(), "nothing to withdraw");
        assertEquals(2, t.refusals("b"), "counted once");

        ReservationTable g = table(eastSide());
        g.place("old", "c6");
        g.place("guide", "c5");
        assertInstanceOf(Waiting.class, g.request("old", route("c6", "c5", "c4")));
        assertInstanceOf(Waiting.class, g.request("guide", route("c5", "c6", "c7"), true), "the guide case: old makes way");
        assertEquals(List.of("old"), g.takeDisplaced().stream().map(Refused::robot).toList());
        assertEquals(1, g.refusals("old"));
        assertEquals(0, g.refusals("guide"));
        Refused byGuide = assertInstanceOf(Refused.class, g.request("old", route("c6", "c5", "c4")), "refused before, but the guide does not make way");
        assertEquals(List.of("old", "guide"), byGuide.cycle());
        assertTrue(g.takeDisplaced().isEmpty());
        assertTrue(g.waiting("guide").isPresent());
    }

    /**
     * The dock in the 5-courier run: the robot waiting in a dead end to come out cannot make way, so an older asker at its
     * door is refused as before (the dead end's robot was displaced, had nowhere to go, and the asker was asked to make
     * way after all, round after round).
     */
    @Test
    void aRobotWaitingInADeadEndIsNotDisplacedByAge() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c4").node("lobby").node("dock")
                .edge("c0", "c4").edge("c4", "lobby").edge("lobby", "dock").build();
        ReservationTable t = table(map);
        t.place("old", "lobby");
        t.place("x", "c4");
        assertInstanceOf(Waiting.class, t.request("x", route("c4", "lobby", "dock")));
        assertInstanceOf(Refused.class, t.request("old", route("lobby", "c4", "c0")), "head to head: old is refused once");
        t.remove("x");
        assertEquals(1, t.refusals("old"));
        t.place("docked", "dock");
        assertInstanceOf(Waiting.class, t.request("docked", route("dock", "lobby", "c4", "c0")));
        Refused r = assertInstanceOf(Refused.class, t.request("old", route("lobby", "dock")), "older, but docked has nowhere to go");
        assertEquals(List.of("old", "docked"), r.cycle());
        assertTrue(t.takeDisplaced().isEmpty());
        assertTrue(t.waiting("docked").isPresent());
    }

    /**
     * Session 14: a courier on its way to charge below its reserve (urgent) is treated like a guide in rule 3. Head to
     * head on the east side's single lane it does not make way (the plain robot of the cycle is refused instead), and a
     * plain robot refused more often does not displace it by age: before, each step aside cost it 0.5 % a metre and the
     * 5-courier runs ended with a battery empty on the way to the dock.
     */
    @Test
    void anUrgentRobotDoesNotMakeWayAndIsNotDisplacedByAge() {
        ReservationTable t = table(eastSide());
        t.place("plain", "c5");
        t.place("low", "c6");
        assertInstanceOf(Waiting.class, t.request("plain", route("c5", "c6", "c7")));
        assertInstanceOf(Waiting.class, t.request("low", route("c6", "c5", "c4"), Precedence.URGENT), "the urgent robot queues for c5");
        List<Refused> displaced = t.takeDisplaced();
        assertEquals(List.of("plain"), displaced.stream().map(Refused::robot).toList());
        assertEquals(List.of("plain", "low"), displaced.get(0).cycle());
        assertTrue(displaced.get(0).reason().contains("low, which drives to charge below its reserve, would wait for each other; plain makes way"),
                displaced.get(0).reason());
        assertEquals(Precedence.URGENT, t.precedence("low"));
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()));

        // plain, refused once now against low's 0, asks again: by age it would displace low, but low is urgent
        Refused again = assertInstanceOf(Refused.class, t.request("plain", route("c5", "c6", "c7")), "refused more often, but not displacing the urgent robot");
        assertEquals(List.of("plain", "low"), again.cycle());
        assertTrue(t.takeDisplaced().isEmpty());
        assertTrue(t.waiting("low").isPresent(), "low keeps its wait");
        assertEquals(2, t.refusals("plain"));

        // plain steps aside is not possible on this lane (c4 is in low's way); it drives back to c4 and on: low gets c5
        assertInstanceOf(Granted.class, t.request("plain", route("c5", "c4")));
        assertEquals(List.of("low"), driveBase(t, "plain").granted().stream().map(Granted::robot).toList());
    }

    /** Among robots with precedence nobody is displaced: two urgent robots, or an urgent robot and a guide, refuse the asker as two guides do. */
    @Test
    void twoUrgentRobotsOrAnUrgentRobotAndAGuideRefuseTheAsker() {
        for (Precedence other : List.of(Precedence.URGENT, Precedence.GUIDE)) {
            ReservationTable t = table(eastSide());
            t.place("a", "c5");
            t.place("b", "c6");
            assertInstanceOf(Waiting.class, t.request("a", route("c5", "c6", "c7"), other));
            Refused r = assertInstanceOf(Refused.class, t.request("b", route("c6", "c5", "c4"), Precedence.URGENT), "against " + other);
            assertEquals(List.of("b", "a"), r.cycle());
            assertTrue(t.takeDisplaced().isEmpty());
            assertTrue(t.waiting("a").isPresent());
            // and the other way round: the guide or urgent asker does not displace the urgent robot waiting
            ReservationTable u = table(eastSide());
            u.place("a", "c5");
            u.place("b", "c6");
            assertInstanceOf(Waiting.class, u.request("b", route("c6", "c5", "c4"), Precedence.URGENT));
            assertInstanceOf(Refused.class, u.request("a", route("c5", "c6", "c7"), other), other + " against urgent");
            assertTrue(u.takeDisplaced().isEmpty());
        }
    }

    /**
     * The dock: a dead end whose door is the lobby's centre, where nobody waits, so a courier on its way to charge waits
     * at c4 for the dock, and the courier charging there needs c4 to come out. Refusing the one inside left both where
     * they were (and, urgent, the one at c4 was asked by nobody to make way): the one waiting to go in is refused
     * instead, wherever it waits, and steps out of the way; the one inside comes out, then it goes in.
     */
    @Test
    void aRobotWaitingFurtherOutToGoIntoTheDeadEndTheAskerComesOutOfMakesWayUrgentOrNot() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c4").node("c5").node("lobby").node("dock")
                .edge("c0", "c4").edge("c4", "c5").edge("c4", "lobby").edge("lobby", "dock")
                .area(Kind.CORRIDOR, "hall", 1, "lobby", "c4-lobby", "lobby-dock").build();
        ReservationTable t = table(map);
        t.place("docked", "dock");
        t.place("low", "c4");
        Waiting w = assertInstanceOf(Waiting.class, t.request("low", route("c4", "lobby", "dock"), Precedence.URGENT));
        assertEquals(List.of("docked"), w.queued().blockers());
        assertInstanceOf(Waiting.class, t.request("docked", route("dock", "lobby", "c4", "c5")), "queued behind low, which makes way");
        List<Refused> displaced = t.takeDisplaced();
        assertEquals(List.of("low"), displaced.stream().map(Refused::robot).toList());
        assertEquals("deadlock avoided: low waits at c4 to go into the dead end dock, and docked in there can only come out through lobby; low makes way",
                displaced.get(0).reason());
        assertTrue(t.waiting("low").isEmpty());
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()));
        // low steps aside to c0 (off docked's way), docked comes out, low goes in
        assertInstanceOf(Granted.class, t.request("low", route("c4", "c0")));
        assertEquals(List.of("docked"), driveBase(t, "low").granted().stream().map(Granted::robot).toList());
        driveBase(t, "docked");
        assertInstanceOf(Granted.class, t.request("docked", route("c4", "c5")));
        driveBase(t, "docked");
        assertInstanceOf(Granted.class, t.request("low", route("c0", "c4", "lobby", "dock"), Precedence.URGENT));
    }

    /**
     * A robot whose battery ran empty is lost where it stands (rule 4): requests through it are refused at once with the
     * reason, and the table stops counting it (its aging count and its precedence end; back on the map, it starts afresh).
     */
    @Test
    void aRobotLostWithAnEmptyBatteryIsNotWaitedForNorCounted() {
        ReservationTable t = table(eastSide());
        t.place("a", "c6");
        t.place("b", "c5");
        assertInstanceOf(Waiting.class, t.request("a", route("c6", "c5", "c4"), Precedence.URGENT));
        assertInstanceOf(Refused.class, t.request("b", route("c5", "c6", "c7"), Precedence.URGENT));
        assertEquals(1, t.refusals("b"));
        t.cancel("a");
        t.lost("b", "battery empty at c5");
        assertEquals(0, t.refusals("b"));
        assertEquals(Precedence.PLAIN, t.precedence("b"));
        Refused r = assertInstanceOf(Refused.class, t.request("a", route("c6", "c5", "c4"), Precedence.URGENT), "not waited for");
        assertEquals("node 'c5' is blocked by robot b, lost there (battery empty at c5)", r.reason());
        assertTrue(r.cycle().isEmpty(), "no deadlock refusal: nobody is counted for it");
        assertEquals(0, t.refusals("a"));
        assertThrows(IllegalStateException.class, () -> t.request("b", route("c5", "c4")), "a lost robot asks for nothing");
        t.remove("b");
        t.place("b", "c5");
        assertEquals(0, t.refusals("b"));
        assertInstanceOf(Granted.class, t.request("b", route("c5", "c4")));
    }
}
