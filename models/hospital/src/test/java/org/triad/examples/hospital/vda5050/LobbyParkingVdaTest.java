package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.LobbyParking;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * The models' moves into and out of the lobby and its charge under traffic control, as {@code ./triad serve --robots
 * vda5050:} drives them: the couriers report the dock or the parking spot they stand on, a move out starts there, a
 * move into the lobby ends on a free spot, and a charge drives onto the dock, a node of the map, and off it again. Real
 * Mosquitto, two couriers in the simulated building, its own process.
 */
class LobbyParkingVdaTest {
    @Test
    void aCourierChargesOnTheDockAndParksOnAFreeSpotAndTheTableKnowsWhereEachStands() throws Exception {
        Path dir = Path.of("target", "vda5050", "lobbyParking");
        List<String> log = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 2, 10, dir, "--battery", "90");
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add)) {
            RemoteAgv one = master.agv("courier-1");
            RemoteAgv two = master.agv("courier-2");
            assertTrue(one.awaitOnline() && two.awaitOnline(), building.output());
            assertEquals(LobbyParking.DOCK, one.state().orElseThrow().lastNodeId(), "courier-1 starts on the dock");
            assertEquals("lobby.1", two.state().orElseThrow().lastNodeId(), "courier-2 on the first spot");
            TrafficControl traffic = new TrafficControl(HospitalTraffic.map(new HospitalFloor()), 300, log::add);
            assertTrue(traffic.place(one.name(), LobbyParking.DOCK) && traffic.place(two.name(), "lobby.1"));
            try (VdaHospital h1 = new VdaHospital(master, "courier-1", traffic, 10, 30);
                    VdaHospital h2 = new VdaHospital(master, "courier-2", traffic, 10, 30)) {
                assertEquals("lobby", h2.courier().loc().name(), "the models see the lobby");
                assertTrue(h1.courier().move(h1.objects().waypoint("lobby"), h1.objects().waypoint("c4")), one.lastFailure() + "\n" + log);
                assertEquals("c4", one.state().orElseThrow().lastNodeId());

                assertTrue(h2.courier().recharge(h2.objects().waypoint("lobby")), two.lastFailure() + "\n" + log + "\n" + building.output());
                assertTrue(two.state().orElseThrow().batteryState().batteryCharge() > 95, "charged full on the dock (from 90 % less the 6 m there), then drove a few metres off it");
                String parked2 = two.state().orElseThrow().lastNodeId();
                assertTrue(LobbyParking.spots().contains(parked2), "off the dock onto a spot: " + parked2);
                assertTrue(building.output().contains("lobby.1 -> lobby -> lobby.dock"), "it drove onto the dock: " + building.output());

                assertTrue(h1.courier().move(h1.objects().waypoint("c4"), h1.objects().waypoint("lobby")), one.lastFailure() + "\n" + log);
                String parked1 = one.state().orElseThrow().lastNodeId();
                assertTrue(LobbyParking.spots().contains(parked1), "into the lobby means onto a free spot: " + parked1);
                assertNotEquals(parked2, parked1);
                assertEquals("lobby", h1.courier().loc().name());
                assertEquals(List.of(parked1), traffic.read(t -> t.base(one.name())), "the table has it where it parked");
                assertEquals(List.of(parked2), traffic.read(t -> t.base(two.name())));
                boolean dockFree = traffic.read(t -> t.holders(t.map().node(LobbyParking.DOCK)).isEmpty());
                assertTrue(dockFree, "the dock is free for the next");
            }
            assertTrue(building.lines("contact courier-").isEmpty(), building.output());
        }
    }
}
