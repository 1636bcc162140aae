package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.Status;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.RemoteLift;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.protocol.AgvState;

import generated.hospital.tasks.CollectAndDeliver;
import generated.hospital.tasks.GoTo;

/**
 * The two-floor building ({@code ./triad robot}'s process) driven over VDA 5050 on a real Mosquitto, its pharmacy door
 * and its lift reached by the hospital's world binding over the device protocol: a delivery from the pharmacy on
 * floor 0 to ward 4 on floor 1 passes the door and rides the lift; a door that does not answer and a lift that stops
 * between floors each end the task with that reason on Status.
 */
class TwoFloorsVdaTest {
    private final List<Status> statuses = new CopyOnWriteArrayList<>();

    @Test
    void aDeliveryFromThePharmacyToAWardUpstairsPassesTheDoorAndRidesTheLift() throws Exception {
        Path dir = Path.of("target", "vda5050", "twoFloors");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 40, dir);
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { });
                VdaHospital h = new VdaHospital(master, "courier-1", 60, 120)) {
            assertTrue(h.courier().agv().awaitOnline(), building.output());
            RefArcRun run = h.run(new CollectAndDeliver(h.objects().item("insulin"), h.objects().room("pharmacy"), h.objects().room("ward4")),
                    statuses::add);
            assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), run.log() + "\n" + building.output());
            String actions = succeeded();
            assertTrue(actions.contains("passDoor(pharmacyDoor, c0, pharmacy)"), actions);
            assertTrue(actions.contains("ride(lift, c7, d1)"), actions);
            AgvState s = h.courier().agv().state().orElseThrow();
            assertEquals("ward4", s.lastNodeId());
            assertTrue(s.loads() == null || s.loads().isEmpty(), "the insulin was put down in ward 4: " + s.loads());
            assertTrue(s.agvPosition().x() > 40, "the courier is on floor 1, east of floor 0 in the plane: " + s.agvPosition());
            assertFalse(building.lines("agv courier-1: carried by the lift from lift0 to lift1").isEmpty(), building.output());
        }
    }

    /**
     * Devices that do not answer (the building runs without them): a door, then, on the same building, a lift. Each ends
     * its task with the device's reason on Status, never a hang (one building for both: its start is the test's cost).
     */
    @Test
    void aDoorAndThenALiftThatDoNotAnswerEachEndTheTaskWithTheReasonNotAHang() throws Exception {
        Path dir = Path.of("target", "vda5050", "silentDevices");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 40, dir, "--devices", "off");
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { });
                VdaHospital h = new VdaHospital(master, "courier-1", 1, 1)) {
            assertTrue(h.courier().agv().awaitOnline(), building.output());
            RefArcRun run = h.run(new GoTo(h.objects().room("pharmacy")), statuses::add);
            assertEquals(RefArcRun.Outcome.ABORTED, run.outcome(), run.log().toString());
            String failed = failed();
            assertTrue(failed.contains("door 'pharmacyDoor' did not answer the request OPEN within 1.0 s (it never reported a state: is the device online?)"),
                    failed);
            assertTrue(last(Status.TaskAborted.class).contains("pharmacyDoor"), last(Status.TaskAborted.class));
            assertEquals("c0", h.courier().agv().state().orElseThrow().lastNodeId(), "the courier waits before the door");

            statuses.clear();
            run = h.run(new GoTo(h.objects().room("ward5")), statuses::add);
            assertEquals(RefArcRun.Outcome.ABORTED, run.outcome(), run.log().toString());
            failed = failed();
            assertTrue(failed.matches("(?s)action Building\\.ride\\(lift, c7, d1\\) failed: [^\n]*lift 'lift' did not answer the request for floor 0"
                    + " within 1\\.0 s \\(it never reported a state: is the device online\\?\\).*"), failed);
            String aborted = last(Status.TaskAborted.class);
            assertTrue(aborted.startsWith("task GoTo(ward5) aborted at goal IsAt(ward5): action Building.ride(lift, c7, d1) failed: ")
                    && aborted.contains("lift 'lift' did not answer"), aborted);
            assertEquals("c7", h.courier().agv().state().orElseThrow().lastNodeId(), "the courier waits at the landing, not in a cabin that never came");
        }
    }

    @Test
    void aLiftThatStopsBetweenFloorsEndsTheTaskWithTheReasonOnStatus() throws Exception {
        Path dir = Path.of("target", "vda5050", "brokenLift");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 40, dir, "--break-lift-at", "0");
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { });
                VdaHospital h = new VdaHospital(master, "courier-1", 60, 120)) {
            assertTrue(h.courier().agv().awaitOnline(), building.output());
            RefArcRun run = h.run(new GoTo(h.objects().room("ward5")), statuses::add);
            assertEquals(RefArcRun.Outcome.ABORTED, run.outcome(), run.log() + "\n" + building.output());
            String failed = failed();
            assertTrue(failed.matches("(?s)action Building\\.ride\\(lift, c7, d1\\) failed: [^\n]*lift 'lift' stopped between floors 0 and 1.*"), failed);
            // RefArc re-planned on the lift's reason; from inside the stuck cabin no plan reaches ward 5, so it aborts
            String replans = statuses.stream().filter(x -> x instanceof Status.Replanning).map(Status::toString).collect(Collectors.joining("\n"));
            assertTrue(replans.matches("(?s)replanning IsAt\\(ward5\\) \\(1 of 3\\): action Building\\.ride\\(lift, c7, d1\\) failed: [^\n]*"
                    + "lift 'lift' stopped between floors 0 and 1.*"), replans);
            // the abort names the lift's fault, not only the planner's "no plan" from inside the stuck cabin
            String aborted = last(Status.TaskAborted.class);
            assertTrue(aborted.matches("task GoTo\\(ward5\\) aborted at goal IsAt\\(ward5\\): action Building\\.ride\\(lift, c7, d1\\) failed: .*"
                    + "lift 'lift' stopped between floors 0 and 1.*; planning from there failed: .*"), aborted);
            AgvState s = h.courier().agv().state().orElseThrow();
            assertEquals("lift0", s.lastNodeId(), "the courier is stuck in the cabin it entered on floor 0");
            assertTrue(s.agvPosition().x() < 30, "still in floor 0's cabin, west of floor 1 in the plane: " + s.agvPosition());
        }
    }

    /**
     * What {@code ./triad run --robots vda5050:} sends for the world's device actions ({@code ModelAgvActors}): an order
     * whose edge carries a {@code passDoor} or {@code ride} action with the model's arguments; the simulated AGV has its
     * building open the door or bring the lift, and the AGV ends where the edge ends.
     */
    @Test
    void theSimulatedAgvPassesADoorAndRidesTheLiftAsEdgeActions() throws Exception {
        Path dir = Path.of("target", "vda5050", "edgeActions");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 40, dir);
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { })) {
            RemoteAgv agv = master.agv("courier-1");
            assertTrue(agv.awaitOnline(), building.output());
            assertEquals("lobby", agv.state().orElseThrow().lastNodeId());
            assertTrue(agv.drive("lobby", "c4") && agv.drive("c4", "c0"), agv.lastFailure() + "\n" + building.output());
            assertTrue(agv.traverse("c0", "pharmacy", "passDoor", java.util.Map.of("d", "pharmacyDoor")), agv.lastFailure() + "\n" + building.output());
            assertEquals("pharmacy", agv.state().orElseThrow().lastNodeId());
            assertTrue(agv.traverse("pharmacy", "c0", "passDoor", java.util.Map.of("d", "pharmacyDoor")), agv.lastFailure() + "\n" + building.output());
            assertTrue(agv.drive("c0", "c4") && agv.drive("c4", "c5") && agv.drive("c5", "c6") && agv.drive("c6", "c7"),
                    agv.lastFailure() + "\n" + building.output());
            assertTrue(agv.traverse("c7", "d1", "ride", java.util.Map.of("l", "lift")), agv.lastFailure() + "\n" + building.output());
            AgvState s = agv.state().orElseThrow();
            assertEquals("d1", s.lastNodeId());
            assertTrue(s.agvPosition().x() > 35, "on floor 1, east of floor 0 in the plane: " + s.agvPosition());
            assertEquals(SimulatedAgv.mapId(1), s.agvPosition().mapId(), "its position is on floor 1's map");
        }
    }

    /**
     * Two robots' bindings call the lift at once over master control's one connection (each its own device link, as
     * {@code VdaHospital} has): the lift queues the second request, holds its door open at the first floor for the robot
     * it came for, then serves the second; each call sees its own answer, although the lift's next state names the other.
     */
    @Test
    void twoRobotsQueuedAtTheLiftAreEachServedInTurn() throws Exception {
        Path dir = Path.of("target", "vda5050", "liftQueue");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 40, dir);
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { });
                DeviceLink one = DeviceLink.over(master.link(), line -> { });
                DeviceLink two = DeviceLink.over(master.link(), line -> { })) {
            RemoteLift upstairs = new RemoteLift(one, "lift", "courier-1", 60);
            RemoteLift downstairs = new RemoteLift(two, "lift", "courier-2", 60);
            java.util.concurrent.CompletableFuture<Boolean> up = java.util.concurrent.CompletableFuture.supplyAsync(() -> upstairs.call(1));
            java.util.concurrent.CompletableFuture<Boolean> down = java.util.concurrent.CompletableFuture.supplyAsync(() -> downstairs.call(0));
            assertTrue(up.get(90, java.util.concurrent.TimeUnit.SECONDS), upstairs.lastFailure() + "\n" + building.output());
            assertTrue(down.get(90, java.util.concurrent.TimeUnit.SECONDS), downstairs.lastFailure() + "\n" + building.output());
            // and once more the other way round, the cabin now at one of the two floors
            up = java.util.concurrent.CompletableFuture.supplyAsync(() -> upstairs.call(1));
            down = java.util.concurrent.CompletableFuture.supplyAsync(() -> downstairs.call(0));
            assertTrue(up.get(90, java.util.concurrent.TimeUnit.SECONDS) && down.get(90, java.util.concurrent.TimeUnit.SECONDS),
                    upstairs.lastFailure() + " / " + downstairs.lastFailure() + "\n" + building.output());
        }
    }

    private String succeeded() {
        return statuses.stream().filter(s -> s instanceof Status.ActionSucceeded).map(Status::toString).collect(Collectors.joining("\n"));
    }

    private String failed() {
        return statuses.stream().filter(s -> s instanceof Status.ActionFailed).map(Status::toString).collect(Collectors.joining("\n"));
    }

    private String last(Class<? extends Status> type) {
        return statuses.stream().filter(type::isInstance).map(Status::toString).reduce((a, b) -> b).orElse("none");
    }
}
