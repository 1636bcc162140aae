package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.Status;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.mqtt.ConformanceMonitor;
import org.triad.vda5050.protocol.Messages.AgvPosition;

import generated.hospital.tasks.CollectAndDeliver;

/** The simulated courier as a VDA 5050 robot: its errors, its instant actions, its factsheet, on a real Mosquitto. */
class VdaRobotTest {
    @Test
    void aClosedDoorIsAnErrorInTheRobotsStateAndRefArcReplansRoundTheRing() {
        List<Status> statuses = new CopyOnWriteArrayList<>();
        Path dir = Path.of("target", "vda5050", "closedDoor");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                ConformanceMonitor monitor = ConformanceMonitor.on(broker.url())) {
            try (SimulatedAgv agv = new SimulatedAgv(broker.url(), "courier-1", 42, 50, dir, line -> { });
                    MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { })) {
                agv.hospital().sim().at(40).closeDoor(HospitalFloor.FIRE_DOOR);
                agv.start();
                VdaHospital h = new VdaHospital(master, "courier-1");
                RefArcRun run = h.run(new CollectAndDeliver(h.objects().item("gauze"), h.objects().room("storage"), h.objects().room("ward1")),
                        statuses::add);
                assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), run.log().toString());
                String failed = statuses.stream().filter(s -> s instanceof Status.ActionFailed).map(Status::toString).findFirst().orElse("");
                assertTrue(failed.startsWith("action Courier.move(c2, c3) failed") && failed.contains("DOOR_CLOSED"), failed);
                assertTrue(run.log().stream().anyMatch(l -> l.startsWith("plan for Delivered(gauze, ward1): Courier.move(c2, c1)")),
                        "re-planned round the ring: " + run.log());
                assertFalse(h.building().adj(h.objects().waypoint("c2"), h.objects().waypoint("c3")), "the robot reports the edge blocked");
            }
            assertEquals(List.of(), monitor.violations());
        }
    }

    @Test
    void instantActionsPauseResumeAndRequestTheFactsheet() throws Exception {
        Path dir = Path.of("target", "vda5050", "instantActions");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                ConformanceMonitor monitor = ConformanceMonitor.on(broker.url())) {
            try (SimulatedAgv agv = new SimulatedAgv(broker.url(), "courier-2", 42, 5, null, line -> { }).start();
                    MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, line -> { })) {
                RemoteAgv robot = master.agv("courier-2");
                assertTrue(robot.awaitOnline());
                assertTrue(robot.instantAction("factsheetRequest", Map.of()), robot.lastFailure().toString());
                assertEquals("Triad simulated courier", robot.factsheet().orElseThrow().at("/typeSpecification/seriesName").asText());
                CompletableFuture<Boolean> drive = CompletableFuture.supplyAsync(() -> robot.drive("lobby", "c4"));
                // paused while it drives: wait for the state that says so (a fixed sleep raced the order on a loaded machine)
                long deadline = System.nanoTime() + 30_000_000_000L;
                while (!robot.state().map(s -> s.driving()).orElse(false) && !drive.isDone() && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                }
                RemoteAgv pauser = master.agv("courier-2");
                assertTrue(pauser.instantAction("startPause", Map.of()));
                Thread.sleep(300);
                AgvPosition held = robot.state().orElseThrow().agvPosition();
                Thread.sleep(500);
                AgvPosition still = robot.state().orElseThrow().agvPosition();
                assertEquals(Boolean.TRUE, robot.state().orElseThrow().paused());
                assertEquals(held.x(), still.x(), 1e-9, "paused: the robot holds still");
                assertEquals(held.y(), still.y(), 1e-9);
                assertFalse(drive.isDone());
                assertTrue(pauser.instantAction("stopPause", Map.of()));
                assertTrue(drive.get(), robot.lastFailure().toString());
                assertEquals("c4", robot.state().orElseThrow().lastNodeId());
                assertTrue(agv.statesSent() >= 5, "state on every change");
                assertFalse(robot.instantAction("selfDestruct", Map.of()));
                assertTrue(robot.lastFailure().orElseThrow().contains("selfDestruct failed: unsupported instant action"),
                        robot.lastFailure().toString());
                assertFalse(robot.nodeAction("c4", "drop", Map.of("loadId", "syringe")), "the robot does not carry the syringe");
                assertTrue(robot.lastFailure().orElseThrow().startsWith("drop at c4 failed on AGV triad/courier-2: drop failed"),
                        robot.lastFailure().toString());
            }
            assertEquals(List.of(), monitor.violations());
        }
    }
}
