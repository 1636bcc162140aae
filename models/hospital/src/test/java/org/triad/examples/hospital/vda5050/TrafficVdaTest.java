package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import org.triad.building.traffic.Resource;
import org.triad.building.traffic.Resource.Kind;
import org.triad.building.traffic.TrafficMap;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;
import org.triad.vda5050.mqtt.ConformanceMonitor;
import org.triad.vda5050.protocol.AgvState;

/**
 * Traffic control through a real Mosquitto and simulated couriers: orders with base and horizon, order
 * updates as stretches are granted, a robot that waits for a corridor or a door instead of failing, and a
 * rogue AGV driving beyond its base stopped as a safety error. Each courier drives in a hospital of its own
 * (one building with many robots is issue #20's), all in the same coordinates: the test checks from the
 * positions they report that two robots are never in the single-lane corridor at once.
 */
class TrafficVdaTest {
    /** The west corridor of the ring (x 0..2.4 m, y 7.4..13 m): one robot at a time. */
    private static boolean inWestCorridor(AgvState s) {
        return s.agvPosition() != null && s.agvPosition().x() < 2.4 && s.agvPosition().y() > 7.4 && s.agvPosition().y() < 13;
    }

    private final List<String> log = new CopyOnWriteArrayList<>();
    private final List<SimulatedAgv> agvs = new ArrayList<>();
    private final ExecutorService pool = Executors.newFixedThreadPool(3);
    private MosquittoBroker broker;
    private ConformanceMonitor monitor;
    private MasterControl master;

    /**
     * The hospital's ring as traffic control sees it: corridor waypoints wide enough for {@code junction}
     * robots, the west and east corridors for one, the fire door and every room door for one.
     */
    static TrafficMap hospital(int junction) {
        TrafficMap.Builder b = TrafficMap.builder();
        for (String c : List.of("c1", "c2", "c3", "c4", "c5", "c6")) {
            b.node(c, junction);
        }
        b.node("lobby", 3);
        for (String r : List.of("storage", "xray", "ward1", "ward2", "ward3")) {
            b.node(r, 1);
        }
        b.edge("c1", "c2").edge("c2", "c3").edge("c4", "c5").edge("c5", "c6").edge("c1", "c4").edge("c3", "c6");
        b.area(Kind.CORRIDOR, "west", 1, "c1-c4").area(Kind.CORRIDOR, "east", 1, "c3-c6").area(Kind.DOOR, "fireDoor", 1, "c2-c3");
        String[][] rooms = { { "storage", "c1" }, { "xray", "c2" }, { "ward1", "c3" }, { "lobby", "c4" }, { "ward3", "c5" }, { "ward2", "c6" } };
        for (String[] r : rooms) {
            b.edge(r[0], r[1]).area(Kind.DOOR, r[0] + "Door", 1, r[0] + "-" + r[1]);
        }
        return b.build();
    }

    @BeforeEach
    void start() {
        Path dir = Path.of("target", "vda5050", "traffic");
        broker = MosquittoBroker.start(dir.resolve("broker"));
        monitor = ConformanceMonitor.on(broker.url());
        master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add);
    }

    @AfterEach
    void stop() {
        agvs.forEach(SimulatedAgv::close);
        pool.shutdownNow();
        master.close();
        List<String> violations = monitor.violations();
        monitor.close();
        broker.close();
        assertEquals(List.of(), violations, "every message conforms to the VDA 5050 schemas");
    }

    private RemoteAgv agv(String serial, boolean rogue) {
        SimulatedAgv a = new SimulatedAgv(broker.url(), serial, 1, 20, null, log::add);
        agvs.add(rogue ? a.ignoringBase().start() : a.start());
        return master.agv(serial);
    }

    @Test
    void headToHeadOnTheSingleLaneCorridorBothArriveOneAfterTheOther() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(2), 60, log::add);
        RemoteAgv r1 = agv("courier-1", false);
        RemoteAgv r2 = agv("courier-2", false);
        assertTrue(r1.driveRoute(List.of("lobby", "c4", "c1"), traffic), r1.lastFailure() + "\n" + log);

        AtomicBoolean both = new AtomicBoolean();
        AtomicBoolean sampling = new AtomicBoolean(true);
        Future<?> sampler = pool.submit(() -> {
            // one last sample after sampling is switched off: a robot's arrival may be the state its drive
            // returned on, seen after the previous sample
            for (boolean last = false; !last; ) {
                last = !sampling.get();
                AgvState s1 = r1.state().orElseThrow();
                AgvState s2 = r2.state().orElseThrow();
                if (inWestCorridor(s1) && inWestCorridor(s2)) {
                    both.set(true);
                }
                Thread.sleep(10);
            }
            return null;
        });
        Future<Boolean> south = pool.submit(() -> r1.driveRoute(List.of("c1", "c4", "c5"), traffic));
        Future<Boolean> north = pool.submit(() -> r2.driveRoute(List.of("lobby", "c4", "c1", "c2"), traffic));
        assertTrue(south.get(120, TimeUnit.SECONDS), r1.lastFailure() + "\n" + log);
        assertTrue(north.get(120, TimeUnit.SECONDS), r2.lastFailure() + "\n" + log);
        sampling.set(false);
        sampler.get(10, TimeUnit.SECONDS);
        assertEquals("c5", r1.state().orElseThrow().lastNodeId());
        assertEquals("c2", r2.state().orElseThrow().lastNodeId());
        assertFalse(both.get(), "two robots were in the single-lane corridor at once");
        assertEquals(1, (int) traffic.read(t -> t.stats().waits(Kind.CORRIDOR).size()), "one of them waited for the corridor\n" + log);
        assertTrue(log.stream().anyMatch(l -> l.contains("courier-") && l.contains("/1 ")), "the base was extended by an order update\n" + log);
    }

    @Test
    void twoRobotsForOneDoorOnePassesTheOtherWaitsAndPassesNext() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(2), 60, log::add);
        RemoteAgv r1 = agv("courier-1", false);
        RemoteAgv r2 = agv("courier-2", false);
        Future<Boolean> first = pool.submit(() -> r1.driveRoute(List.of("lobby", "c4", "c5"), traffic));
        Future<Boolean> second = pool.submit(() -> r2.driveRoute(List.of("lobby", "c4", "c1"), traffic));
        assertTrue(first.get(120, TimeUnit.SECONDS), r1.lastFailure() + "\n" + log);
        assertTrue(second.get(120, TimeUnit.SECONDS), r2.lastFailure() + "\n" + log);
        assertEquals(1, (int) traffic.read(t -> t.stats().waits(Kind.DOOR).size()), "one waited for the lobby's door\n" + log);
        Resource door = traffic.read(t -> t.map().area("lobbyDoor").orElseThrow());
        assertEquals(0, (int) traffic.read(t -> t.holders(door).size()), "the door is free again");
    }

    @Test
    void aRobotThatCannotGetItsCorridorWithinTheBoundFailsWithTheReason() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(1), 2, log::add);
        RemoteAgv r1 = agv("courier-1", false);
        RemoteAgv r2 = agv("courier-2", false);
        assertTrue(r1.driveRoute(List.of("lobby", "c4"), traffic), r1.lastFailure() + "\n" + log);
        // courier-1 stays at c4, a junction for one: courier-2 waits at the lobby, then gives up with the reason
        assertFalse(r2.driveRoute(List.of("lobby", "c4", "c5"), traffic));
        String why = r2.lastFailure().orElseThrow();
        assertTrue(why.contains("courier-2 waits at lobby for") && why.contains("node 'c4'") && why.contains("triad/courier-1")
                && why.contains("for more than 2.0 s"), why);
        assertEquals(org.triad.runtime.app.Failure.Cause.CONGESTION, r2.lastFailureWithCause().orElseThrow().cause(),
                "the building's congestion, not the robot's fault: a fleet queues the task again");
        assertEquals("lobby", r2.state().orElseThrow().lastNodeId(), "it never left its decision point");
        assertTrue(traffic.waits().isEmpty());
    }

    @Test
    void aRogueAgvDrivingBeyondItsBaseIsReportedAsASafetyErrorAndStopped() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(1), 60, log::add);
        RemoteAgv r1 = agv("courier-1", false);
        RemoteAgv rogue = agv("courier-2", true);
        assertTrue(r1.driveRoute(List.of("lobby", "c4"), traffic), r1.lastFailure() + "\n" + log);
        // c4 is held by courier-1: courier-2's base is only the lobby, c4 its horizon; it drives there anyway
        assertFalse(rogue.driveRoute(List.of("lobby", "c4", "c5"), traffic));
        String why = rogue.lastFailure().orElseThrow();
        assertTrue(why.contains("safety: AGV triad/courier-2 drove beyond its released base: it reports node 'c4' (sequence 2) but its base ends at 'lobby'"),
                why);
        assertTrue(waitFor(() -> Boolean.TRUE.equals(rogue.state().orElseThrow().paused()), 20), "stopped with startPause\n" + log);
        assertEquals(Double.POSITIVE_INFINITY, traffic.read(t -> t.expectedWait("c5", "c4")), "nobody is sent to where it stands");
    }

    @Test
    void aRobotKilledInTheCorridorIsLostThereAfterItsLastWillAndTheOthersGoOnElsewhere() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(2), 60, log::add);
        RemoteAgv r2 = agv("courier-2", false);
        try (AgvProcess dying = AgvProcess.start(broker.url(), "courier-1", 5, Path.of("target", "vda5050", "traffic"))) {
            RemoteAgv r1 = master.agv("courier-1");
            assertTrue(waitFor(() -> r1.state().isPresent(), 120), "its own JVM came up\n" + dying.output());
            Future<Boolean> west = pool.submit(() -> r1.driveRoute(List.of("lobby", "c4", "c1"), traffic));
            assertTrue(waitFor(() -> r1.state().map(s -> "c4".equals(s.lastNodeId()) && s.driving()).orElse(false), 60),
                    "in the corridor: " + r1.lastFailure() + "\n" + log + "\n" + dying.output());
            dying.kill();
            assertFalse(west.get(60, TimeUnit.SECONDS));
            assertTrue(r1.lastFailure().orElseThrow().contains("CONNECTIONBROKEN"), r1.lastFailure().orElseThrow());
        }
        assertTrue(r2.driveRoute(List.of("lobby", "c4"), traffic), r2.lastFailure() + "\n" + log);
        assertFalse(r2.driveRoute(List.of("c4", "c1", "c2"), traffic), "not driven into the lost robot");
        assertTrue(r2.lastFailure().orElseThrow().contains("corridor 'west' is blocked by robot triad/courier-1, lost there (CONNECTIONBROKEN"),
                r2.lastFailure().orElseThrow());
        assertEquals(org.triad.runtime.app.Failure.Cause.FAULT, r2.lastFailureWithCause().orElseThrow().cause(),
                "a lost robot in the way is for an operator to clear, not congestion that passes");
        assertTrue(r2.driveRoute(List.of("c4", "c5", "c6"), traffic), "the others go on elsewhere: " + r2.lastFailure() + "\n" + log);
    }

    /** The east passage of the ring (x 21.6..24 m, y 7.4..13 m), the lift's cabin in {@link #withLift}. */
    private static boolean inEastPassage(AgvState s) {
        return s.agvPosition() != null && s.agvPosition().x() > 21.6 && s.agvPosition().y() > 7.4 && s.agvPosition().y() < 13;
    }

    /**
     * The ring with a lift for one instead of the east corridor: the simulated courier's floor has no second
     * floor (the two-floor building is issue #20's), so the passage from c6 to c3 stands in for the ride, a
     * resource of kind LIFT the robots queue for like any lift.
     */
    static TrafficMap withLift() {
        TrafficMap.Builder b = TrafficMap.builder();
        for (String c : List.of("c1", "c2", "c3", "c4", "c5", "c6")) {
            b.node(c, 2);
        }
        b.node("lobby", 3);
        b.edge("c1", "c2").edge("c2", "c3").edge("c4", "c5").edge("c5", "c6").edge("c1", "c4").edge("c3", "c6");
        b.area(Kind.CORRIDOR, "west", 1, "c1-c4").area(Kind.LIFT, "lift", 1, "c3-c6").area(Kind.DOOR, "fireDoor", 1, "c2-c3");
        b.edge("lobby", "c4").area(Kind.DOOR, "lobbyDoor", 1, "lobby-c4");
        return b.build();
    }

    /**
     * A ring of three corridors for one between three junctions for one (c1, c4, c6): west c1-c4, south c4-c5-c6,
     * north-east c6-c3-c2-c1; the lobby and ward2 are side rooms to get out of the way into.
     */
    static TrafficMap threeCorridors() {
        TrafficMap.Builder b = TrafficMap.builder();
        for (String c : List.of("c1", "c2", "c3", "c4", "c5", "c6")) {
            b.node(c, 1);
        }
        b.node("lobby", 3).node("ward2", 1);
        b.edge("c1", "c2").edge("c2", "c3").edge("c4", "c5").edge("c5", "c6").edge("c1", "c4").edge("c3", "c6").edge("lobby", "c4").edge("ward2", "c6");
        b.area(Kind.CORRIDOR, "west", 1, "c1-c4").area(Kind.CORRIDOR, "south", 1, "c4-c5", "c5", "c5-c6")
                .area(Kind.CORRIDOR, "northEast", 1, "c3-c6", "c3", "c2-c3", "c2", "c1-c2");
        return b.build();
    }

    @Test
    void twoRobotsForTheLiftOneRidesTheOtherWaitsAndRidesNext() throws Exception {
        TrafficControl traffic = new TrafficControl(withLift(), 120, log::add);
        RemoteAgv r1 = agv("courier-1", false);
        RemoteAgv r2 = agv("courier-2", false);
        assertTrue(r1.driveRoute(List.of("lobby", "c4", "c5", "c6"), traffic), r1.lastFailure() + "\n" + log);
        assertTrue(r2.driveRoute(List.of("lobby", "c4", "c5", "c6"), traffic), r2.lastFailure() + "\n" + log);
        Resource lift = traffic.read(t -> t.map().area("lift").orElseThrow());
        AtomicBoolean both = new AtomicBoolean();
        List<String> arrivals = new CopyOnWriteArrayList<>();
        AtomicBoolean sampling = new AtomicBoolean(true);
        Future<?> sampler = pool.submit(() -> {
            // one last sample after sampling is switched off: a robot's arrival may be the state its drive
            // returned on, seen after the previous sample
            for (boolean last = false; !last; ) {
                last = !sampling.get();
                AgvState s1 = r1.state().orElseThrow();
                AgvState s2 = r2.state().orElseThrow();
                both.compareAndSet(false, inEastPassage(s1) && inEastPassage(s2));
                for (AgvState s : List.of(s1, s2)) {
                    if ("c3".equals(s.lastNodeId()) && !arrivals.contains(s.serialNumber())) {
                        arrivals.add(s.serialNumber());
                    }
                }
                Thread.sleep(10);
            }
            return null;
        });
        Future<Boolean> first = pool.submit(() -> r1.driveRoute(List.of("c6", "c3", "c2"), traffic));
        assertTrue(waitFor(() -> traffic.read(t -> t.holders(lift).contains("triad/courier-1")), 60), "courier-1 got the lift\n" + log);
        Future<Boolean> second = pool.submit(() -> r2.driveRoute(List.of("c6", "c3"), traffic));
        assertTrue(waitFor(() -> traffic.waits().stream().anyMatch(w -> w.robot().equals("triad/courier-2") && w.reason().contains("lift 'lift'"))
                || !traffic.read(t -> t.holders(lift).contains("triad/courier-1")), 60), "courier-2 queued for the lift\n" + log);
        assertTrue(first.get(120, TimeUnit.SECONDS), r1.lastFailure() + "\n" + log);
        assertTrue(second.get(120, TimeUnit.SECONDS), r2.lastFailure() + "\n" + log);
        sampling.set(false);
        sampler.get(10, TimeUnit.SECONDS);
        assertEquals(List.of("courier-1", "courier-2"), arrivals, "they rode in the order they asked");
        assertFalse(both.get(), "two robots were in the lift at once");
        assertEquals(1, (int) traffic.read(t -> t.stats().waits(Kind.LIFT).size()), "courier-2 waited for the lift, then rode\n" + log);
        assertEquals(0, (int) traffic.read(t -> t.holders(lift).size()), "the lift is free again");
    }

    /**
     * The default wherever traffic control drives ({@code ./triad serve}): a robot refused as a deadlock steps aside by
     * itself before its call fails, out of the way of the robots it would have waited for, and they go on.
     */
    @Test
    void threeRobotsInACycleOfThreeCorridorsDoNotDeadlockTheOneRefusedStepsAsideAndTheOthersArrive() throws Exception {
        TrafficControl traffic = new TrafficControl(threeCorridors(), 120, log::add);
        RemoteAgv a = agv("courier-1", false);
        RemoteAgv b = agv("courier-2", false);
        RemoteAgv c = agv("courier-3", false);
        assertTrue(a.driveRoute(List.of("lobby", "c4", "c5", "c6"), traffic), a.lastFailure() + "\n" + log);
        assertTrue(b.driveRoute(List.of("lobby", "c4", "c1"), traffic), b.lastFailure() + "\n" + log);
        assertTrue(c.driveRoute(List.of("lobby", "c4"), traffic), c.lastFailure() + "\n" + log);
        // each wants the next junction round the ring, where another stands: courier-1's wait would close a cycle of three
        Future<Boolean> third = pool.submit(() -> c.driveRoute(List.of("c4", "c5", "c6"), traffic));
        assertTrue(waitFor(() -> traffic.waits().size() == 1, 60), "courier-3 waits for c6\n" + log);
        Future<Boolean> second = pool.submit(() -> b.driveRoute(List.of("c1", "c4", "lobby"), traffic));
        assertTrue(waitFor(() -> traffic.waits().size() == 2, 60), "courier-2 waits for c4\n" + log);
        assertEquals(Set.of(), cycle(traffic.read(t -> t.waitsFor())));
        assertFalse(a.driveRoute(List.of("c6", "c3", "c2", "c1"), traffic), "refused, not queued in a cycle");
        String why = a.lastFailure().orElseThrow();
        assertTrue(why.contains("deadlock avoided: triad/courier-1 would wait for triad/courier-2"), why);
        assertEquals(org.triad.runtime.app.Failure.Cause.CONGESTION, a.lastFailureWithCause().orElseThrow().cause(), why);
        // it stepped aside to the only free stop node next to c6 (c3 and c5 lie in corridors), out of the others' way
        assertTrue(why.endsWith("stepped aside to 'ward2', out of the others' way"), why);
        assertEquals("ward2", a.state().orElseThrow().lastNodeId());
        assertTrue(third.get(180, TimeUnit.SECONDS), c.lastFailure() + "\n" + log);
        assertTrue(second.get(180, TimeUnit.SECONDS), b.lastFailure() + "\n" + log);
        assertEquals(List.of("ward2", "lobby", "c6"), List.of(a.state().orElseThrow().lastNodeId(), b.state().orElseThrow().lastNodeId(),
                c.state().orElseThrow().lastNodeId()));
        assertTrue(traffic.waits().isEmpty());
        assertEquals(List.of("ward2"), traffic.read(t -> t.base(a.name())));
    }

    /** A robot on a cycle of the wait-for graph, or none (depth first). */
    private static Set<String> cycle(java.util.Map<String, Set<String>> g) {
        for (String start : g.keySet()) {
            java.util.Deque<String> todo = new java.util.ArrayDeque<>(g.get(start));
            Set<String> seen = new java.util.HashSet<>();
            while (!todo.isEmpty()) {
                String n = todo.pop();
                if (n.equals(start)) {
                    return Set.of(start);
                }
                if (seen.add(n)) {
                    todo.addAll(g.getOrDefault(n, Set.of()));
                }
            }
        }
        return Set.of();
    }

    @Test
    void aRobotThatDiesWhileIdleIsLostWhereItStandsAfterItsLastWillAndNotDrivenInto() throws Exception {
        TrafficControl traffic = new TrafficControl(hospital(1), 60, log::add);
        RemoteAgv r2 = agv("courier-2", false);
        try (AgvProcess dying = AgvProcess.start(broker.url(), "courier-1", 5, Path.of("target", "vda5050", "traffic"))) {
            RemoteAgv r1 = master.agv("courier-1");
            assertTrue(waitFor(() -> r1.state().isPresent(), 120), "its own JVM came up\n" + dying.output());
            assertTrue(r1.driveRoute(List.of("lobby", "c4", "c1"), traffic), r1.lastFailure() + "\n" + log + "\n" + dying.output());
            dying.kill(); // idle at c1: no route running to notice
            assertTrue(waitFor(() -> traffic.read(t -> t.isLost("triad/courier-1")), 60), "lost after its last will and the grace\n" + log);
        }
        assertTrue(traffic.read(t -> t.holding("triad/courier-1")).stream().allMatch(r -> r.id().equals("c1")), "it holds only where it stands");
        assertTrue(r2.driveRoute(List.of("lobby", "c4"), traffic), r2.lastFailure() + "\n" + log);
        assertFalse(r2.driveRoute(List.of("c4", "c1", "c2"), traffic), "not driven into the lost robot");
        String why = r2.lastFailure().orElseThrow();
        assertTrue(why.contains("node 'c1' is blocked by robot triad/courier-1, lost there (CONNECTIONBROKEN (its last will) while idle"), why);
        assertTrue(r2.driveRoute(List.of("c4", "c5", "c6"), traffic), "the others go on elsewhere: " + r2.lastFailure() + "\n" + log);
    }

    private static boolean waitFor(java.util.function.BooleanSupplier c, int seconds) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (System.nanoTime() < end) {
            if (c.getAsBoolean()) {
                return true;
            }
            Thread.sleep(20);
        }
        return false;
    }
}
