package org.triad.vda5050.master;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.triad.building.traffic.Decision;
import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Precedence;
import org.triad.building.traffic.TrafficMap;
import org.triad.vda5050.protocol.AgvState;
import org.triad.vda5050.protocol.Messages.AgvError;
import org.triad.vda5050.protocol.Messages.Edge;
import org.triad.vda5050.protocol.Messages.ErrorLevel;
import org.triad.vda5050.protocol.Messages.Reference;
import org.triad.vda5050.protocol.Messages.EdgeState;
import org.triad.vda5050.protocol.Messages.Node;
import org.triad.vda5050.protocol.Messages.NodeState;

/**
 * {@link RouteDrive} and {@link TrafficControl} without a broker: the states an AGV would send are fed to the drive as
 * master control feeds them, the orders it sends are recorded. Fast, and exact about the order of events.
 */
class RouteDriveTest {
    /** A ring of four nodes for one robot each: a - b - c - d - a, every node a stop node. */
    private static TrafficMap ring() {
        return TrafficMap.builder().node("a").node("b").node("c").node("d").edge("a", "b").edge("b", "c").edge("c", "d").edge("d", "a").build();
    }

    private record Sent(String orderId, int updateId, List<Node> nodes, List<Edge> edges) {
    }

    private static AgvState state(String orderId, String lastNode, int lastSeq, boolean driving) {
        return new AgvState(0, "2026-01-01T00:00:00.00Z", "2.1.0", "triad", "a", orderId, 0, null, lastNode, lastSeq,
                driving ? List.of(new NodeState("x", lastSeq + 2, null, null, true)) : List.of(),
                driving ? List.of(new EdgeState("e", lastSeq + 1, null, true)) : List.of(), null, null, null, driving, null, null, null,
                List.of(), null, "AUTOMATIC", List.of(), null, null);
    }

    /**
     * The gridlock the fleet's benchmark found (couriers 4, 8, 2, 5 each waiting for the next one's node, every 120 s the
     * same waits): a call that ended at its decision point (a wait over the bound) left the robot holding the node it
     * came from, which nobody reported it passed, and a robot waiting for that node had no edge in the wait-for graph
     * (the table takes a stopped robot to hold its decision point only). A waits for B, B for C, C for A's old node: a
     * cycle deadlock avoidance did not see. The AGV's states after the call ended are now reported, and the old node is
     * freed as it reaches its decision point.
     */
    @Test
    void aCallEndedAtItsDecisionPointKeepsItsBaseUpToThereAndReleasesWhatLiesBehindAsTheAgvGetsThere() throws InterruptedException {
        TrafficControl traffic = new TrafficControl(ring(), 0.2, line -> { });
        assertTrue(traffic.place("A", "d"));
        assertTrue(traffic.place("B", "b"));
        assertTrue(traffic.place("C", "c"));
        List<Sent> orders = new ArrayList<>();
        RouteDrive drive = new RouteDrive("A", List.of("d", "a", "b"), "o1", traffic, (id, u, n, e) -> orders.add(new Sent(id, u, n, e)),
                why -> { });
        assertTrue(drive.start().isEmpty());
        assertEquals(List.of("d", "a"), traffic.read(t -> t.base("A")), "granted up to the stop node a; b (B's) asked for ahead");
        assertTrue(traffic.read(t -> t.waiting("A")).isPresent());
        // B waits for C (at its decision point), C waits for d: held by A, which is on its way to a
        assertFalse(traffic.read(t -> t.request("B", List.of("b", "c"))) instanceof Granted);
        assertFalse(traffic.read(t -> t.request("C", List.of("c", "d"))) instanceof Granted);
        assertEquals(Set.of(), traffic.read(t -> t.waitsFor().get("C")),
                "C waits for d, but A will not hold d once at its decision point: no edge C -> A, no cycle (A -> B -> C) refused");

        // A's wait for b goes over the bound while it drives d -> a: its call ends at its decision point a
        RouteDrive.Verdict v = RouteDrive.Verdict.RUNNING;
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (v.failure() == null && System.nanoTime() < deadline) {
            v = drive.onState(state("o1", "d", 0, true));
            Thread.sleep(20);
        }
        assertNotNull(v.failure(), "the wait over the bound ends the call");
        assertTrue(v.failure().contains("the wait bound"), v.failure());
        Sent last = orders.get(orders.size() - 1);
        assertEquals(List.of("a"), last.nodes().stream().map(Node::nodeId).toList(), "the order now ends at the decision point");
        drive.abandon(false);
        assertEquals(List.of("d", "a"), traffic.read(t -> t.base("A")), "the AGV still drives to a: its base stays reserved up to there");
        assertTrue(traffic.read(t -> t.waiting("A")).isEmpty(), "its wait is withdrawn");

        // the AGV reaches a and stops: reported, d is freed and C is granted it
        assertFalse(drive.trail(state("o1", "d", 0, true)), "still on its way");
        assertTrue(drive.trail(state("o1", "a", 2, false)));
        assertEquals(List.of("a"), traffic.read(t -> t.base("A")));
        assertInstanceOf(Granted.class, traffic.take("C").orElseThrow(), "C was waiting for d, which A no longer holds");
    }

    @Test
    void aRobotIdleAtItsDecisionPointWhosePassingWasNotReportedIsReleasedBehindWhenItStartsAgain() {
        TrafficControl traffic = new TrafficControl(ring(), 60, line -> { });
        assertTrue(traffic.place("A", "d"));
        assertTrue(traffic.place("C", "c"));
        RouteDrive drive = new RouteDrive("A", List.of("d", "a"), "o1", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(drive.start().isEmpty());
        assertFalse(traffic.read(t -> t.request("C", List.of("c", "d"))) instanceof Granted);
        // the call was given up on (no state reported a) but the AGV stands idle at a, its decision point
        assertTrue(traffic.relocate("A", "a"));
        assertEquals(List.of("a"), traffic.read(t -> t.base("A")));
        assertInstanceOf(Granted.class, traffic.take("C").orElseThrow());
        assertEquals(Map.of(), traffic.read(t -> t.waitsFor()));
    }

    /**
     * The two-robot cycle that jammed the service's mixed benchmark for its whole run (courier-3 in the storage room,
     * courier-4 waiting at its door c1 to go in): the one inside used to be refused again and again, with nowhere to step
     * aside to, and the one at the door, with no free neighbour either, was never asked to move. Now the one at the door
     * is refused (it makes way, waiting for a neighbour if it must) and the one inside waits for the door and comes out.
     */
    @Test
    void aRobotWaitingAtTheDoorOfADeadEndMakesWayForTheRobotComingOut() {
        TrafficMap map = TrafficMap.builder().node("x").node("c0").node("c1").node("c2").node("c3").node("storage")
                .edge("x", "c0").edge("c0", "c1").edge("c1", "c2").edge("c2", "c3").edge("c1", "storage").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "storage"));
        assertTrue(traffic.place("B", "c1"));
        assertTrue(traffic.place("C", "c0"));
        assertTrue(traffic.place("D", "c2"));
        assertTrue(traffic.aside("B").isEmpty(), "c0 and c2 are taken: no free neighbour");
        RouteDrive in = new RouteDrive("B", List.of("c1", "storage"), "oB", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(in.start().isEmpty());
        assertTrue(traffic.read(t -> t.waiting("B")).isPresent(), "B waits at the door for A's room");

        RouteDrive out = new RouteDrive("A", List.of("storage", "c1", "c2", "c3"), "oA", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(out.start().isEmpty(), "A is not refused: it waits for the door");
        assertTrue(traffic.read(t -> t.waiting("A")).isPresent());
        RouteDrive.Verdict v = in.onState(state("oB", "c1", 0, false));
        assertNotNull(v.failure(), "B's wait for the room ends");
        assertTrue(v.congestion());
        assertTrue(v.failure().contains("B makes way"), v.failure());
        assertTrue(in.deadlockAvoided(), "so B steps aside (RemoteAgv.stepAsideAfter)");
        in.abandon(false);

        // nowhere free to go: B queues for a neighbour (c0, where C stands idle; not A's room) and goes there when C leaves
        assertEquals(java.util.Optional.of("c0"), traffic.wayOut("B"));
        RouteDrive aside = new RouteDrive("B", List.of("c1", "c0"), "oB2", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(aside.start().isEmpty());
        assertTrue(traffic.read(t -> t.waiting("B")).isPresent());
        assertInstanceOf(Granted.class, traffic.read(t -> t.request("C", List.of("c0", "x"))));
        traffic.passed("C", "x");
        assertNull(aside.onState(state("oB2", "c1", 0, false)).failure(), "B is granted c0");
        assertNull(aside.onState(state("oB2", "c0", 2, false)).failure());
        assertInstanceOf(Granted.class, traffic.take("A").orElseThrow(), "B left the door: A comes out");
        assertEquals(List.of("storage", "c1"), traffic.read(t -> t.base("A")));
        assertEquals(Map.of(), traffic.read(t -> t.waitsFor()));
    }

    /**
     * The AGV failed an edge while a stretch was granted to it: the drive fails with the AGV's error, and no order update
     * is sent after it (the AGV, its order aborted short of the decision point, rejected one: {@code noRouteError: the
     * order starts at c6 but the AGV is at c3}, and that rejection became the drive's reason).
     */
    @Test
    void anEdgeTheAgvFailedEndsTheDriveWithItsErrorAndNoUpdateIsSentAfterIt() {
        TrafficControl traffic = new TrafficControl(ring(), 600, line -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("C", "c"));
        List<Sent> orders = new ArrayList<>();
        RouteDrive drive = new RouteDrive("A", List.of("a", "b", "c"), "o1", traffic, (id, u, n, e) -> orders.add(new Sent(id, u, n, e)),
                why -> { });
        assertTrue(drive.start().isEmpty());
        assertEquals(List.of("a", "b"), traffic.read(t -> t.base("A")), "c is C's: A waits for it");
        assertInstanceOf(Granted.class, traffic.read(t -> t.request("C", List.of("c", "d"))));
        traffic.passed("C", "d"); // c is granted to A, in its mailbox
        int sent = orders.size();
        AgvState failed = new AgvState(0, "2026-01-01T00:00:00.00Z", "2.1.0", "triad", "a", "o1", 0, null, "a", 0, List.of(), List.of(), null, null,
                null, false, null, null, null, List.of(), null, "AUTOMATIC",
                List.of(new AgvError("noProgress", List.of(new Reference("orderId", "o1"), new Reference("edgeId", "a-b")), "obstructed", ErrorLevel.FATAL)),
                List.of(), null);
        RouteDrive.Verdict v = drive.onState(failed);
        assertEquals("noProgress: obstructed", v.failure());
        assertEquals(sent, orders.size(), "no update stitched at b, where the AGV is not");
        drive.abandon(false);
        assertEquals(List.of("a", "b"), traffic.read(t -> t.base("A")), "it may stand on the edge to b: it keeps a-b and b, not c");
    }

    /**
     * The service's mixed benchmark: courier-5 stepped aside from {@code c0} into the pharmacy, traffic control had it
     * there, its idle AGV (and so the plan) said {@code c0}, and every drive from {@code c0} was refused as a FAULT until
     * the robot was out of dispatch. The AGV's report wins when its node has room: the map is put right and the drive starts.
     */
    @Test
    void anIdleAgvReportingANodeOffItsBaseIsPutThereOnTheMapWhenTheNodeHasRoom() {
        TrafficMap map = TrafficMap.builder().node("pharmacy").node("c0").node("c1").node("c2")
                .edge("pharmacy", "c0").edge("c0", "c1").edge("c1", "c2").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "c0"));
        assertTrue(traffic.place("B", "c1"));
        assertEquals(java.util.Optional.of("pharmacy"), traffic.aside("A"));
        RouteDrive aside = new RouteDrive("A", List.of("c0", "pharmacy"), "oA", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(aside.start().isEmpty());
        assertNull(aside.onState(state("oA", "pharmacy", 2, false)).failure());
        assertEquals("pharmacy", traffic.decisionPoint("A"));

        // the AGV reports c0, idle: the map follows it, and the pharmacy is free again
        assertTrue(traffic.relocate("A", "c0"));
        assertEquals(List.of("c0"), traffic.read(t -> t.base("A")));
        assertTrue(traffic.place("C", "pharmacy"), "nobody holds the pharmacy now");

        // a node others hold has no room: the map is left as it was, and the drive is refused (not the robot's fault)
        assertFalse(traffic.relocate("A", "pharmacy"), "C stands in the pharmacy");
        assertEquals("c0", traffic.decisionPoint("A"));
    }

    /**
     * courier-3 guiding Alice from c1 to c4 while courier-6 at c4 waits for c1 (the service's benchmark): the guide's drive
     * is queued, not refused; courier-6's drive ends having made way (so {@code RemoteAgv} steps it aside), and once it is
     * out of c4 the guide goes. A guide is never the robot asked to make way for a refused one either.
     */
    @Test
    void aRobotGuidingAPersonIsQueuedAndTheRobotItWouldWaitForMakesWay() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c1").node("c4").node("c5")
                .edge("c0", "c1").edge("c1", "c4").edge("c4", "c5").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("guide", "c1"));
        assertTrue(traffic.place("other", "c4"));
        RouteDrive other = new RouteDrive("other", List.of("c4", "c1", "c0"), "oO", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(other.start().isEmpty());
        assertTrue(traffic.read(t -> t.waiting("other")).isPresent(), "other waits for c1");

        org.triad.vda5050.protocol.Messages.Action guide = new org.triad.vda5050.protocol.Messages.Action("guide", "g1", null,
                org.triad.vda5050.protocol.Messages.BlockingType.HARD,
                List.of(new org.triad.vda5050.protocol.Messages.ActionParameter("personId", "alice")));
        RouteDrive guiding = new RouteDrive("guide", List.of("c1", "c4"), "oG", traffic, (id, u, n, e) -> { }, why -> { }, List.of(guide));
        assertTrue(guiding.start().isEmpty(), "the guide is not refused");
        assertTrue(traffic.read(t -> t.waiting("guide")).isPresent(), "it waits for c4");
        assertTrue(traffic.askToMakeWay("other", List.of("other", "guide")).isEmpty(), "a guide is not asked to make way");

        RouteDrive.Verdict v = other.onState(state("oO", "c4", 0, false));
        assertNotNull(v.failure());
        assertTrue(v.congestion());
        assertTrue(other.madeWay(), v.failure());
        assertTrue(other.deadlockAvoided(), "RemoteAgv.stepAsideAfter moves it");
        other.abandon(false);
        assertEquals(java.util.Optional.of("c5"), traffic.wayOut("other"));
        RouteDrive aside = new RouteDrive("other", List.of("c4", "c5"), "oO2", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(aside.start().isEmpty());
        assertNull(aside.onState(state("oO2", "c5", 2, false)).failure());
        assertNull(guiding.onState(state("oG", "c1", 0, false)).failure(), "the guide is granted c4");
        assertEquals(List.of("c1", "c4"), traffic.read(t -> t.base("guide")));
    }

    /**
     * The benchmark's longest standstill: courier-8's first stretch (c0 -> c1) was granted and sent, the next one refused at
     * once, and the call cut its base back to c0 while the AGV drove to c1 and stood there, its order waiting for an update
     * that never came; c1 went to courier-6, which the AGV blocked there for 400 simulated s. A refusal right after the
     * order went out now ends the order at the decision point, like a refusal later on, and the base stays up to there.
     */
    @Test
    void aRefusalRightAfterTheFirstStretchWasSentEndsTheOrderAtTheDecisionPointAndKeepsTheBaseUpToThere() {
        TrafficMap line = TrafficMap.builder().node("a").node("b").node("c").edge("a", "b").edge("b", "c").build();
        TrafficControl traffic = new TrafficControl(line, 60, l -> { });
        assertTrue(traffic.place("A", "a"));
        traffic.read(t -> t.block(t.map().node("c"), "a bed stands there"));
        List<Sent> orders = new ArrayList<>();
        RouteDrive drive = new RouteDrive("A", List.of("a", "b", "c"), "o1", traffic, (id, u, n, e) -> orders.add(new Sent(id, u, n, e)),
                why -> { });
        String why = drive.start().orElseThrow();
        assertTrue(why.contains("a bed stands there"), why);
        assertEquals(2, orders.size(), "the order, then its update ending it at the decision point");
        assertEquals(List.of("a", "b", "c"), orders.get(0).nodes().stream().map(Node::nodeId).toList());
        assertTrue(orders.get(0).edges().get(0).released(), "a -> b was released to the AGV: it drives there");
        assertEquals(1, orders.get(1).updateId());
        assertEquals(List.of("b"), orders.get(1).nodes().stream().map(Node::nodeId).toList(), "the horizon deleted: the order ends at b");
        assertTrue(drive.endedAtDecisionPoint());
        assertEquals(List.of("a", "b"), traffic.read(t -> t.base("A")), "b stays A's: its AGV drives there");

        assertTrue(drive.trail(state("o1", "b", 2, false)), "the AGV reports b and stands: nothing more to report");
        assertEquals(List.of("b"), traffic.read(t -> t.base("A")), "a, behind it, is released");
    }

    /**
     * A robot refused head to head steps aside off the way the robots of its cycle wait for. The benchmark's west corridor:
     * courier-8 at c4, courier-4 at c1 waiting for the lane c1-c4, which runs over c0 (one zone with it). Stepping aside
     * to c0 left courier-8 in courier-4's way, where it was refused again and stepped back to c4: ten refusals in a row.
     */
    @Test
    void aRobotRefusedHeadToHeadStepsAsideOffTheWayTheOthersWaitFor() {
        TrafficMap west = TrafficMap.builder().node("c0").node("c1").node("c4").node("c5").node("c6").edge("c1", "c0").edge("c0", "c4").edge("c1", "c4")
                .edge("c4", "c5").edge("c5", "c6").area(org.triad.building.traffic.Resource.Kind.ZONE, "passing-c0", 1, "c0", "c1-c4").build();
        TrafficControl traffic = new TrafficControl(west, 600, l -> { });
        assertTrue(traffic.place("A", "c1"));
        assertTrue(traffic.place("B", "c4"));
        assertTrue(traffic.place("C", "c5"));
        assertFalse(traffic.request("A", List.of("c1", "c4")) instanceof Granted, "A waits for B's c4");
        var refused = assertInstanceOf(org.triad.building.traffic.Decision.Refused.class, traffic.request("B", List.of("c4", "c1")));
        assertEquals(Set.of("A", "B"), Set.copyOf(refused.cycle()));
        assertEquals(java.util.Optional.of("c0"), traffic.wayOut("B"), "without the cycle: the first of the least wanted places, c0");
        assertEquals(java.util.Optional.of("c5"), traffic.wayOut("B", refused.cycle()),
                "c0 and the lane over it are what A waits for: B queues for c5 instead, off A's way");
    }

    /**
     * The dyn4j benchmark's full ground-floor ring (session 12's cause 4): chains of couriers each waiting for the next one's
     * node ended at a courier standing on the ring after a failed drive. A robot whose wait went over the bound now clears
     * the way into a free room off the node it stands at (never one a waiting robot is heading for), and a robot stepping
     * aside takes a room before a corridor node.
     */
    @Test
    void aRobotWhoseWaitWentOverTheBoundClearsTheWayIntoAFreeRoomOffTheRing() throws InterruptedException {
        // the ring a - b - c - d - a with a room off a, b and c each
        TrafficMap map = TrafficMap.builder().node("a").node("b").node("c").node("d").node("ra").node("rb").node("rc")
                .edge("a", "b").edge("b", "c").edge("c", "d").edge("d", "a").edge("a", "ra").edge("b", "rb").edge("c", "rc").build();
        TrafficControl traffic = new TrafficControl(map, 0.2, l -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("B", "b"));
        assertTrue(traffic.place("C", "c"));
        assertEquals(java.util.Optional.of("ra"), traffic.aside("A"), "the room off a before the free corridor node d");

        RouteDrive drive = new RouteDrive("A", List.of("a", "b", "c"), "o1", traffic, (id, u, n, e) -> { }, why -> { });
        assertTrue(drive.start().isEmpty());
        assertTrue(traffic.read(t -> t.waiting("A")).isPresent(), "A waits for B's node");
        assertTrue(traffic.roomAside("A").isEmpty(), "not while it waits");
        RouteDrive.Verdict v = RouteDrive.Verdict.RUNNING;
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (v.failure() == null && System.nanoTime() < deadline) {
            v = drive.onState(state("o1", "a", 0, false));
            Thread.sleep(20);
        }
        assertTrue(v.failure().contains("the wait bound"), v.failure());
        assertTrue(drive.waitedInVain(), "so RemoteAgv clears the way");
        assertFalse(drive.deadlockAvoided());
        drive.abandon(false);
        assertEquals(java.util.Optional.of("ra"), traffic.roomAside("A"), "a, where it stands, is a corridor node with a free room off it");

        // D, waiting at d for its way to ra, is heading there: A does not take it
        assertTrue(traffic.place("D", "d"));
        assertFalse(traffic.request("D", List.of("d", "c", "b", "a", "ra")) instanceof Granted);
        assertEquals(List.of("d", "c", "b", "a", "ra"), traffic.read(t -> t.heading("D")));
        assertTrue(traffic.roomAside("A").isEmpty(), "ra is where D is heading");
        assertEquals(java.util.Optional.of("rc"), traffic.roomAside("C"), "nobody is heading for rc");
        assertTrue(traffic.place("E", "rb"));
        assertTrue(traffic.roomAside("B").isEmpty(), "E is in rb");
        assertTrue(traffic.roomAside("E").isEmpty(), "E is in a room already");
    }

    /**
     * The 5-courier benchmark on the aging branch: the table displaced a courier for one refused more often, the displaced
     * one had nowhere to step aside, and master control asked the older one to make way after all, round after round,
     * until its battery was empty. A robot refused more often than the one with nowhere to go is not asked.
     */
    @Test
    void aRobotRefusedMoreOftenIsNotAskedToMakeWay() {
        TrafficMap map = TrafficMap.builder().node("s").node("a").node("b").node("t").edge("s", "a").edge("a", "b").edge("b", "t").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("B", "b"));
        for (int i = 0; i < 2; i++) { // B made way twice before (counted, as master control's requests to make way are)
            assertInstanceOf(Decision.Waiting.class, traffic.request("B", List.of("b", "a")));
            traffic.read(t -> t.makeWay("B"));
        }
        assertInstanceOf(Decision.Waiting.class, traffic.request("B", List.of("b", "a")));
        Decision.Refused refused = assertInstanceOf(Decision.Refused.class, traffic.request("A", List.of("a", "b")), "refused fewer times than B");
        assertEquals(Integer.valueOf(2), traffic.<Integer>read(t -> t.refusals("B")));
        assertEquals(Integer.valueOf(1), traffic.<Integer>read(t -> t.refusals("A")));
        assertTrue(traffic.wayOut("B", refused.cycle()).isPresent(), "B could step aside to t");
        assertTrue(traffic.askToMakeWay("A", refused.cycle()).isEmpty(), "but was refused more often than A");
        assertTrue(traffic.read(t -> t.waiting("B")).isPresent());
    }

    /**
     * Session 14: a robot driving to charge below its reserve (urgent) is not displaced by a plain robot; the drive's
     * urgency reaches the table as its precedence.
     */
    @Test
    void anUrgentRobotIsAskedToMakeWayOnlyWhenNoPlainOneCanAndItsDriveReachesTheTableAsUrgent() {
        TrafficMap map = TrafficMap.builder().node("s").node("a").node("b").node("t").edge("s", "a").edge("a", "b").edge("b", "t").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("B", "b"));
        RouteDrive drive = new RouteDrive("B", List.of("b", "a"), "order-1", traffic, (id, update, nodes, edges) -> { }, why -> { }, List.of(), true);
        assertEquals(Precedence.URGENT, drive.precedence());
        assertTrue(drive.start().isEmpty(), "B waits for a");
        assertEquals(Precedence.URGENT, traffic.<Precedence>read(t -> t.precedence("B")));
        Decision.Refused refused = assertInstanceOf(Decision.Refused.class, traffic.request("A", List.of("a", "b")), "A does not displace B");
        assertTrue(traffic.wayOut("B", refused.cycle()).isPresent(), "B could step aside to t");
        assertTrue(traffic.read(t -> t.waiting("B")).isPresent());
        // a plain robot of the cycle is asked first; here there is none, and A has nowhere to go: B's way runs through A's
        // place, so B is asked after all (the ring jammed for good when it never was)
        assertEquals(java.util.Optional.of("B"), traffic.askToMakeWay("A", refused.cycle()));
    }

    /** Of a plain and an urgent robot that could make way for a refused robot with nowhere to go, the plain one is asked. */
    @Test
    void aPlainRobotIsAskedToMakeWayBeforeAnUrgentOne() {
        TrafficMap map = TrafficMap.builder().node("s").node("a").node("b").node("c").node("t").node("u")
                .edge("s", "a").edge("a", "b").edge("b", "c").edge("c", "t").edge("b", "u").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("U", "a"));
        assertTrue(traffic.place("P", "c"));
        assertTrue(traffic.place("R", "b"));
        assertInstanceOf(Decision.Waiting.class, traffic.request("U", List.of("a", "b"), Precedence.URGENT));
        assertInstanceOf(Decision.Waiting.class, traffic.request("P", List.of("c", "b"), Precedence.PLAIN));
        assertEquals(java.util.Optional.of("P"), traffic.askToMakeWay("R", List.of("R", "U", "P")));
    }

    /** A robot lost where its battery ran empty is not waited for: a request through its place is refused at once, with the reason. */
    @Test
    void aRobotLostWithAnEmptyBatteryIsNotWaitedFor() {
        TrafficMap map = TrafficMap.builder().node("s").node("a").node("b").edge("s", "a").edge("a", "b").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("B", "b"));
        traffic.lost("B", "its battery is empty (batteryCharge 0 %) at b: it cannot drive until it is charged");
        Decision.Refused r = assertInstanceOf(Decision.Refused.class, traffic.request("A", List.of("a", "b")));
        assertEquals("node 'b' is blocked by robot B, lost there (its battery is empty (batteryCharge 0 %) at b: it cannot drive until it is charged)",
                r.reason());
        assertTrue(traffic.place("B", "b"), "charged, it is back where it stands");
        assertFalse(traffic.isLost("B"));
    }

    /**
     * A robot getting out of the way of another does not step aside to a place that one holds (here the lane to t runs past
     * a, where A stands: one zone): it would wait there for A, which waits for it to leave. It has no way out then.
     */
    @Test
    void aRobotDoesNotStepAsideIntoAPlaceHeldByTheRobotItMakesWayFor() {
        TrafficMap map = TrafficMap.builder().node("a").node("b").node("t").edge("a", "b").edge("b", "t")
                .area(org.triad.building.traffic.Resource.Kind.ZONE, "passing-a", 1, "a", "b-t").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("A", "a"));
        assertTrue(traffic.place("B", "b"));
        assertEquals(java.util.Optional.of("t"), traffic.wayOut("B", List.of()), "out of nobody's way in particular, t would do");
        assertTrue(traffic.wayOut("B", List.of("A", "B")).isEmpty(), "out of A's way, t is A's");
    }

    /**
     * The lobby's gateway: a robot at c4 whose neighbours on the ring are taken steps aside into the lobby, through the
     * hall's centre (no stop node) onto a free spot, before an urgent robot that needs c4 is asked to make way.
     */
    @Test
    void aRobotWithItsNeighboursTakenStepsAsideThroughAHallOntoAFreeSpot() {
        TrafficMap map = TrafficMap.builder().node("c0").node("c4").node("c5").node("lobby").node("spot").node("dock")
                .edge("c0", "c4").edge("c4", "c5").edge("c4", "lobby").edge("lobby", "spot").edge("lobby", "dock")
                .area(org.triad.building.traffic.Resource.Kind.CORRIDOR, "hall", 1, "lobby", "c4-lobby", "lobby-spot", "lobby-dock").build();
        TrafficControl traffic = new TrafficControl(map, 600, line -> { });
        assertTrue(traffic.place("P", "c4"));
        assertTrue(traffic.place("U", "c5"));
        assertTrue(traffic.place("X", "c0"));
        assertTrue(traffic.place("D", "dock"));
        assertInstanceOf(Decision.Waiting.class, traffic.request("U", List.of("c5", "c4", "c0"), Precedence.URGENT));
        Decision.Refused r = assertInstanceOf(Decision.Refused.class, traffic.request("P", List.of("c4", "c5")));
        assertTrue(traffic.aside("P").isEmpty(), "no free neighbour for one");
        assertEquals(java.util.Optional.of("spot"), traffic.wayOut("P", r.cycle()), "the free spot behind the hall");
        assertEquals(List.of("c4", "lobby", "spot"), traffic.asideRoute("c4", "spot"));
        assertInstanceOf(Decision.Granted.class, traffic.request("P", traffic.asideRoute("c4", "spot")), "one stretch, all or nothing");
    }
}
