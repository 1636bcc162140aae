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
import org.triad.vda5050.master.MasterControl;
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
                AgvProcess building = AgvProcess.building(broker.url(), 1, 20, dir);
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

    @Test
    void aDoorThatDoesNotAnswerEndsTheTaskWithTheReasonOnStatus() throws Exception {
        Path dir = Path.of("target", "vda5050", "silentDoor");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 20, dir, "--devices", "off");
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { });
                VdaHospital h = new VdaHospital(master, "courier-1", 2, 120)) {
            assertTrue(h.courier().agv().awaitOnline(), building.output());
            RefArcRun run = h.run(new GoTo(h.objects().room("pharmacy")), statuses::add);
            assertEquals(RefArcRun.Outcome.ABORTED, run.outcome(), run.log().toString());
            String failed = failed();
            assertTrue(failed.contains("door 'pharmacyDoor' did not answer the request OPEN within 2.0 s (it never reported a state: is the device online?)"),
                    failed);
            assertTrue(last(Status.TaskAborted.class).contains("pharmacyDoor"), last(Status.TaskAborted.class));
            assertEquals("c0", h.courier().agv().state().orElseThrow().lastNodeId(), "the courier waits before the door");
        }
    }

    @Test
    void aLiftThatStopsBetweenFloorsEndsTheTaskWithTheReasonOnStatus() throws Exception {
        Path dir = Path.of("target", "vda5050", "brokenLift");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 20, dir, "--break-lift-at", "0");
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
            assertTrue(last(Status.TaskAborted.class).contains("IsAt(ward5)"), last(Status.TaskAborted.class));
            AgvState s = h.courier().agv().state().orElseThrow();
            assertEquals("lift0", s.lastNodeId(), "the courier is stuck in the cabin it entered on floor 0");
            assertTrue(s.agvPosition().x() < 30, "still in floor 0's cabin, west of floor 1 in the plane: " + s.agvPosition());
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
