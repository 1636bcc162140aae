package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.devices.DeviceMessages.DoorState;
import org.triad.vda5050.devices.RemoteDoor;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * Doors tied to the door reservations ({@link DoorKeeper}), in one simulated building on a real Mosquitto: the lobby
 * door is closed; two couriers leave the lobby one just after the other. Traffic control opens the door for the first, keeps it open
 * while the second waits for the doorway behind it (a door opened for one robot is not closed on the next one), and
 * closes it once both are through. The fire door is not traffic control's to open: a courier facing it closed fails
 * its drive with the building's reason.
 */
class TrafficDoorsTest {
    @Test
    void aDoorOpenedForOneCourierIsNotClosedOnTheNextAndClosesBehindTheLast() throws Exception {
        Path dir = Path.of("target", "vda5050", "trafficDoors");
        List<String> log = new CopyOnWriteArrayList<>();
        List<String> lobbyDoor = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 2, 4, dir); // 4x: courier-1 takes seconds to clear the doorway, so courier-2 asks while it holds it
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add);
                DeviceLink keeperLink = DeviceLink.connect(broker.url(), "traffic-doors-keeper", log::add);
                DeviceLink testLink = DeviceLink.connect(broker.url(), "traffic-doors-test", line -> { });
                DoorKeeper keeper = new DoorKeeper(keeperLink, HospitalTraffic.keptDoors(new HospitalFloor()), 30, log::add)) {
            RemoteAgv one = master.agv("courier-1");
            RemoteAgv two = master.agv("courier-2");
            assertTrue(one.awaitOnline() && two.awaitOnline(), building.output());
            RemoteDoor door = new RemoteDoor(testLink, "lobbyDoor", "traffic-doors-test", 30);
            assertTrue(door.close(), door.lastFailure().toString());
            testLink.subscribe(DeviceMessages.doorStateTopic("lobbyDoor"), DoorState.class, s -> lobbyDoor.add(s.currentMode()));
            awaitLast(lobbyDoor, DeviceMessages.CLOSED, building);
            assertTrue(!HospitalTraffic.keptDoors(new HospitalFloor()).contains(HospitalFloor.FIRE_DOOR), "the fire door is not kept");

            TrafficControl traffic = new TrafficControl(HospitalTraffic.map(new HospitalFloor()), 120, log::add).keepDoors(keeper);
            CompletableFuture<Boolean> east = CompletableFuture.supplyAsync(() -> one.driveRoute(AgvProcess.outOfTheLobby(one, "c4", "c5"), traffic));
            // courier-1 first (it starts on the lobby's dock, courier-2 on a spot): it holds the hall and the doorway when courier-2 asks
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!lobbyDoor.contains(DeviceMessages.OPEN)) {
                assertTrue(System.nanoTime() < deadline, "the lobby door was not opened for courier-1: " + lobbyDoor + "\n" + log);
                Thread.sleep(10);
            }
            CompletableFuture<Boolean> west = CompletableFuture.supplyAsync(() -> two.driveRoute(AgvProcess.outOfTheLobby(two, "c4", "c1"), traffic));
            assertTrue(east.get(180, TimeUnit.SECONDS), one.lastFailure() + "\n" + log + "\n" + building.output());
            assertTrue(west.get(180, TimeUnit.SECONDS), two.lastFailure() + "\n" + log + "\n" + building.output());
            assertTrue(log.stream().anyMatch(l -> l.startsWith("traffic: door 'lobbyDoor' opened for triad/courier-")), log.toString());
            awaitLast(lobbyDoor, DeviceMessages.CLOSED, building);
            int opened = lobbyDoor.indexOf(DeviceMessages.OPEN);
            assertTrue(opened > 0, "traffic control opened the closed door: " + lobbyDoor);
            List<String> after = lobbyDoor.subList(opened, lobbyDoor.size());
            long closings = java.util.stream.IntStream.range(1, after.size())
                    .filter(i -> after.get(i).equals(DeviceMessages.CLOSED) && !after.get(i - 1).equals(DeviceMessages.CLOSED)).count();
            assertEquals(1, closings, "opened once, closed once after both couriers passed (never on the second): " + lobbyDoor + "\n" + log);
            assertTrue(building.lines("contact courier-1 courier-2").isEmpty(), building.output());

            // the fire door stays traffic control's business only as a reservation: closed, the courier's drive fails with why
            RemoteDoor fireDoor = new RemoteDoor(testLink, HospitalFloor.FIRE_DOOR, "traffic-doors-test", 30);
            assertTrue(fireDoor.close(), fireDoor.lastFailure().toString());
            assertTrue(two.driveRoute(List.of("c1", "c2"), traffic), two.lastFailure() + "\n" + log);
            assertTrue(!two.driveRoute(List.of("c2", "c3"), traffic), "the closed fire door stops the courier");
            assertTrue(two.lastFailure().orElseThrow().contains("DOOR_CLOSED"), two.lastFailure().toString());
        }
    }

    private static void awaitLast(List<String> modes, String mode, AgvProcess building) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (modes.isEmpty() || !modes.get(modes.size() - 1).equals(mode)) {
            assertTrue(System.nanoTime() < deadline, "the lobby door never reported " + mode + ": " + modes + "\n" + building.output());
            Thread.sleep(20);
        }
    }
}
