package org.triad.examples.hospital.vda5050;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Waiting;
import org.triad.building.traffic.ReservationTable;
import org.triad.building.traffic.ReservationTable.Changes;
import org.triad.building.traffic.Resource;
import org.triad.building.traffic.TrafficMap;
import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.LobbyParking;

/**
 * The hospital's admission out of the lobby ({@link HospitalTraffic#ADMITTED}), on the table alone (no broker), opt-in ({@code -Dtraffic.admitted=N}): with as many
 * robots out as admitted, a robot leaving the lobby waits there, robots out of the lobby still move (a robot in a room comes
 * out), and the one waiting goes as soon as one comes back.
 */
class HospitalTrafficAdmissionTest {
    private final double[] now = { 0 };

    /** Drives the robot along its whole base, node by node: the requests that granted. */
    private static List<Granted> driveBase(ReservationTable t, String robot) {
        List<Granted> granted = new java.util.ArrayList<>();
        for (String n : List.copyOf(t.base(robot)).subList(1, t.base(robot).size())) {
            Changes c = t.passed(robot, n);
            granted.addAll(c.granted());
        }
        return granted;
    }

    @Test
    void aRobotLeavesTheLobbyOnlyWhileFewerThanTheAdmittedAreOutAndThoseOutAlwaysMove() {
        int admitted = 8;
        TrafficMap map = HospitalTraffic.map(new HospitalFloor(), admitted);
        Resource out = map.area(HospitalTraffic.OUT_OF_THE_LOBBY).orElseThrow();
        assertEquals(admitted, out.capacity());
        assertTrue(HospitalTraffic.map(new HospitalFloor(), 0).area(HospitalTraffic.OUT_OF_THE_LOBBY).isEmpty(), "no limit: no zone");
        ReservationTable t = new ReservationTable(map, () -> now[0]);
        List<String> places = List.of("storage", "xray", "ward1", "ward3", "ward2", "pharmacy", "d2", "ward4", "c5", "c6");
        for (int i = 0; i < admitted; i++) {
            t.place("r" + i, places.get(i));
        }
        String spot = LobbyParking.spots().get(0);
        t.place("lobby-1", spot);
        Waiting w = assertInstanceOf(Waiting.class, t.request("lobby-1", List.of(spot, "lobby", "c4", "c5")));
        assertTrue(w.queued().blocking().contains(out), w.queued().reason());
        assertEquals(admitted, t.holders(out).size());

        // out of the lobby, robots come out of their rooms and drive on: they hold the zone already
        Granted fromWard3 = assertInstanceOf(Granted.class, t.request("r3", List.of("ward3", "c5", "c6")));
        assertEquals(List.of("ward3", "c5"), fromWard3.stretch());
        driveBase(t, "r3");

        // r0 comes back from the storage room to a spot in the lobby: it goes ahead of the waiting one, whose way it is in,
        // and once it is in the lobby the waiting one is admitted
        String home = LobbyParking.spots().get(1);
        List<String> back = List.of("storage", "c1", "c0", "c4", "lobby", home);
        assertInstanceOf(Granted.class, t.request("r0", back));
        driveBase(t, "r0");
        Granted g = null;
        for (int i = 0; i < 3 && !t.base("r0").get(t.base("r0").size() - 1).equals(home); i++) {
            List<String> rest = back;
            String at = t.decisionPoint("r0");
            assertInstanceOf(Granted.class, t.request("r0", rest.subList(rest.indexOf(at), rest.size())));
            for (Granted x : driveBase(t, "r0")) {
                if (x.robot().equals("lobby-1")) {
                    g = x;
                }
            }
        }
        assertEquals(home, t.decisionPoint("r0"));
        assertTrue(g != null, "lobby-1 is admitted as r0 is back in the lobby");
        assertEquals(List.of(spot, "lobby", "c4"), g.stretch());
        assertEquals(admitted, t.holders(out).size());
    }
}
