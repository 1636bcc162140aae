package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.building.traffic.Decision;
import org.triad.building.traffic.ReservationTable;
import org.triad.building.traffic.Resource.Kind;
import org.triad.building.traffic.TrafficBoard;
import org.triad.building.traffic.TrafficMap;

/** The operator page's traffic section: robots waiting longer than a bound, for what and behind whom ({@code /api/traffic}). */
class TrafficWaitsTest {
    @TempDir
    Path dir;

    @Test
    void aRobotWaitingLongerThanTheBoundIsListedWithWhatItWaitsForAndBehindWhom() {
        TrafficMap map = TrafficMap.builder().node("hall-w", 3).node("c1").node("hall-e", 3).edge("hall-w", "c1").edge("c1", "hall-e")
                .area(Kind.CORRIDOR, "west", 1, "c1", "hall-w-c1", "c1-hall-e").build();
        double[] now = { 0 };
        ReservationTable table = new ReservationTable(map, () -> now[0]);
        table.place("triad/courier-1", "hall-w");
        table.place("triad/courier-2", "hall-e");
        assertInstanceOf(Decision.Granted.class, table.request("triad/courier-1", List.of("hall-w", "c1", "hall-e")));
        assertInstanceOf(Decision.Waiting.class, table.request("triad/courier-2", List.of("hall-e", "c1", "hall-w")));
        try (ServiceFixture s = ServiceFixture.start(dir.resolve("db"), "dry:1")) {
            TrafficBoard board = s.service.traffic();
            board.add(() -> TrafficBoard.waiting(table));
            assertEquals(0, s.get("/api/traffic", ServiceFixture.OPERATOR).body().size(), "nobody waited 30 s yet");
            now[0] = 45;
            ServiceFixture.Response r = s.get("/api/traffic", ServiceFixture.OPERATOR);
            assertEquals(200, r.status(), r.body().toString());
            assertEquals(1, r.body().size(), r.body().toString());
            JsonNode w = r.body().get(0);
            assertEquals("triad/courier-2", w.get("robot").asText());
            assertEquals(45.0, w.get("seconds").asDouble());
            assertTrue(w.get("reason").asText().startsWith("triad/courier-2 waits at hall-e for ") && w.get("reason").asText().contains("corridor 'west'"),
                    w.toString());
            assertEquals("triad/courier-1", w.get("heldBy").get(0).asText());
            assertEquals(0, s.get("/api/traffic?over=60", ServiceFixture.OPERATOR).body().size());
            ServiceFixture.Response bad = s.get("/api/traffic?over=soon", ServiceFixture.OPERATOR);
            assertEquals(400, bad.status());
            assertTrue(bad.body().toString().contains("?over= takes the seconds"), bad.body().toString());
            assertEquals(401, s.get("/api/traffic", null).status());
        }
    }
}
