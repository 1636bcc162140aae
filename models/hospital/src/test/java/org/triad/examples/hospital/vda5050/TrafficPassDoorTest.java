package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.master.DoorKeeper;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.RemoteAgv;
import org.triad.vda5050.master.TrafficControl;

/**
 * The models' {@code passDoor} under traffic control (as {@code ./triad serve --robots vda5050:} drives it) is a reserved
 * drive: the table follows the courier through the pharmacy's door and back. It used to be a plain order outside the
 * table: the service's benchmark had a courier come out of the pharmacy to c0 while the table kept it inside, and c0,
 * where it stood, was given to others. Real Mosquitto, the simulated building its own process.
 */
class TrafficPassDoorTest {
    @Test
    void aCourierPassingTheKeptPharmacyDoorIsFollowedByTheTable() throws Exception {
        Path dir = Path.of("target", "vda5050", "trafficPassDoor");
        List<String> log = new CopyOnWriteArrayList<>();
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"));
                AgvProcess building = AgvProcess.building(broker.url(), 1, 10, dir);
                MasterControl master = MasterControl.connect(broker.url(), VdaFaultsTest.TEST_TIMEOUTS, log::add);
                DeviceLink keeperLink = DeviceLink.connect(broker.url(), "traffic-pass-door-keeper", log::add);
                DoorKeeper keeper = new DoorKeeper(keeperLink, HospitalTraffic.keptDoors(new HospitalFloor()), 30, log::add)) {
            RemoteAgv one = master.agv("courier-1");
            assertTrue(one.awaitOnline(), building.output());
            TrafficControl traffic = new TrafficControl(HospitalTraffic.map(new HospitalFloor()), 300, log::add).keepDoors(keeper);
            assertTrue(HospitalTraffic.keptDoors(new HospitalFloor()).contains(HospitalFloor.PHARMACY_DOOR));
            assertTrue(one.driveRoute(List.of("lobby", "c4", "c0"), traffic), one.lastFailure() + "\n" + log);
            try (VdaHospital h = new VdaHospital(master, "courier-1", traffic, 10, 30)) {
                var door = h.objects().door(HospitalFloor.PHARMACY_DOOR);
                assertTrue(h.building().passDoor(door, h.objects().waypoint("c0"), h.objects().waypoint("pharmacy")),
                        one.lastFailure() + "\n" + log + "\n" + building.output());
                assertEquals("pharmacy", one.state().orElseThrow().lastNodeId());
                assertEquals("pharmacy", traffic.read(t -> t.base(one.name()).get(t.base(one.name()).size() - 1)),
                        "the table has the courier where it drove: " + log);
                boolean c0Free = traffic.read(t -> t.holders(t.map().node("c0")).isEmpty());
                assertTrue(c0Free, "c0, behind it, is free");

                assertTrue(h.building().passDoor(door, h.objects().waypoint("pharmacy"), h.objects().waypoint("c0")),
                        one.lastFailure() + "\n" + log + "\n" + building.output());
                assertEquals("c0", one.state().orElseThrow().lastNodeId());
                assertEquals(List.of("c0"), traffic.read(t -> t.base(one.name())), "and back out at c0: " + log);
            }
            assertTrue(building.lines("contact courier-").isEmpty(), building.output());
        }
    }
}
