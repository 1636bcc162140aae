package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * A side-node yield at a dead end, in the simulated building on a real Mosquitto: courier-1 stands in ward 3, a room
 * whose only way out is c5; courier-2, at c5, is sent into ward 3. Courier-2 does not wait at the room's door (where
 * it would shut courier-1 in: courier-1 would be refused as a deadlock, and both would stand until the wait bound):
 * it steps aside to a free neighbouring stop node and waits there for c5 and ward 3 together. Courier-1, sent out,
 * comes out; courier-2 goes in. Both arrive, neither is refused, no contact. Then the other way round: a robot waiting
 * at the door after all, the one inside asks to come out: it is queued for the door, and the one at the door is refused
 * (it makes way), steps aside, and the one inside comes out.
 */
class DeadEndYieldTest {
    @Test
    void aRobotSentIntoATakenDeadEndStepsAsideForTheOneComingOut() throws Exception {
        Path dir = Path.of("target", "vda5050", "deadEndYield");
        List<String> log = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 2, 10, dir); // 10x: the simulated building, paced; what is checked is the order of events, not their time
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add);
                DeviceLink keeperLink = DeviceLink.connect(broker.url(), "dead-end-keeper", log::add);
                DoorKeeper keeper = new DoorKeeper(keeperLink, HospitalTraffic.keptDoors(new HospitalFloor()), 30, log::add)) {
            RemoteAgv one = master.agv("courier-1");
            RemoteAgv two = master.agv("courier-2");
            assertTrue(one.awaitOnline() && two.awaitOnline(), building.output());
            TrafficControl traffic = new TrafficControl(HospitalTraffic.map(new HospitalFloor()), 300, log::add).keepDoors(keeper).stepAside(true);

            assertTrue(one.driveRoute(AgvProcess.outOfTheLobby(one, "c4", "c5", "ward3"), traffic), one.lastFailure() + "\n" + log);
            assertTrue(two.driveRoute(AgvProcess.outOfTheLobby(two, "c4", "c5"), traffic), two.lastFailure() + "\n" + log);

            CompletableFuture<Boolean> in = CompletableFuture.supplyAsync(() -> two.driveRoute(List.of("c5", "ward3"), traffic));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            // courier-2 waits for ward 3, and not at its door: c5 is free for courier-1 to come out
            while (!traffic.read(t -> t.waiting(two.name()).isPresent() && !t.decisionPoint(two.name()).equals("c5"))) {
                assertTrue(System.nanoTime() < deadline, "courier-2 never stepped aside from c5: " + log + "\n" + building.output());
                Thread.sleep(10);
            }
            String aside = traffic.read(t -> t.decisionPoint(two.name()));
            String exit = aside.equals("c4") ? "c6" : "c4";
            assertTrue(one.driveRoute(List.of("ward3", "c5", exit), traffic), one.lastFailure() + "\n" + log + "\n" + building.output());
            assertTrue(in.get(300, TimeUnit.SECONDS), two.lastFailure() + "\n" + log + "\n" + building.output());

            assertEquals(exit, one.state().orElseThrow().lastNodeId());
            assertEquals("ward3", two.state().orElseThrow().lastNodeId());
            assertNotEquals("c5", aside);

            // courier-1 waits at the door after all (its caller drove it without stepping aside) and courier-2, inside, is
            // sent out: not refused (it has no other way out) but queued for the door, and courier-1's wait is refused, so
            // it makes way (it steps aside) and courier-2 comes out
            traffic.stepAside(false);
            assertTrue(one.driveRoute(List.of(exit, "c5"), traffic), one.lastFailure() + "\n" + log);
            CompletableFuture<Boolean> blocked = CompletableFuture.supplyAsync(() -> one.driveRoute(List.of("c5", "ward3"), traffic));
            while (!traffic.read(t -> t.waiting(one.name()).isPresent())) {
                assertTrue(System.nanoTime() < deadline + TimeUnit.SECONDS.toNanos(120), "courier-1 never waited at c5: " + log);
                Thread.sleep(10);
            }
            traffic.stepAside(true);
            assertTrue(two.driveRoute(List.of("ward3", "c5"), traffic), two.lastFailure() + "\n" + log + "\n" + building.output());
            assertEquals("c5", two.state().orElseThrow().lastNodeId());
            assertFalse(blocked.get(300, TimeUnit.SECONDS), "courier-1's drive ended: it made way");
            assertTrue(one.lastFailure().orElseThrow().contains("triad/courier-1 makes way") && one.lastFailure().orElseThrow().contains("stepped aside"),
                    one.lastFailure().orElseThrow());
            assertNotEquals("c5", one.state().orElseThrow().lastNodeId());
            assertTrue(building.lines("contact courier-").isEmpty(), building.output());
        }
    }
}
