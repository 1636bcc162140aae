package org.triad.tests.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * {@code ./triad serve models/hospital --robots sim:2} is one simulated building: both couriers drive in one dyn4j
 * simulation, so one gauze asked for twice is delivered once (the second task waits for it, then is refused with the
 * reason), another courier works at the same time, and the operator's map shows both robots, one gauze and one
 * Alice in one building.
 */
class SimulatedBuildingServiceTest {
    private static final Path HOSPITAL = Path.of("../models/hospital/src/main/models").toAbsolutePath().normalize();
    private static final String OPERATOR = "sim-building-operator";
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Wall-clock bound for a task on a loaded machine: generous, it only stops a hung run. */
    private static final long TASK_MILLIS = 300_000;

    @TempDir
    Path dir;

    @Test
    void twoCouriersInOneSimulatedHospitalDeliverOneGauzeOnceAndShareOneMap() throws Exception {
        try (TriadService s = TriadService.start(new TriadService.Options(HOSPITAL, List.of("sim:2@40"), null, dir.resolve("db"), null,
                "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, "sim-building-submit", AccessTokens.OPERATOR_ENV, OPERATOR)))) {
            ApiClient api = new ApiClient(s.url(), OPERATOR);
            JsonNode before = JSON.readTree(api.get("/api/building"));
            assertEquals(1, count(before.get("layout").get("items"), "gauze"), "one gauze in the building: " + before);
            assertEquals(1, count(before.get("layout").get("people"), "alice"), "one Alice in the building: " + before);

            long first = submit(api, "CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward1\"}");
            long second = submit(api, "CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward1\"}");
            long other = submit(api, "GoTo", "{\"dst\": \"xray\"}");

            // while the first delivery runs, the map shows both couriers on one floor of one building
            JsonNode during = JSON.readTree(api.get("/api/building"));
            Set<String> maps = new HashSet<>();
            List<String> names = new ArrayList<>();
            for (JsonNode r : during.get("robots")) {
                names.add(r.get("name").asText());
                assertFalse(r.get("pose").isNull(), "every courier has a position: " + r);
                maps.add(r.get("pose").get("mapId").asText());
            }
            assertEquals(List.of("sim-1", "sim-2"), names, during.toString());
            assertEquals(Set.of(during.get("layoutMap").asText()), maps, "one map for both: " + during);

            JsonNode a = await(api, first);
            JsonNode b = await(api, second);
            JsonNode c = await(api, other);
            assertEquals("completed", a.get("state").asText(), a.toString());
            assertEquals("completed", c.get("state").asText(), c.toString());
            assertNotEquals(a.get("robot").asText(), c.get("robot").asText(), "the other courier drove at the same time: " + a + " " + c);
            assertEquals("refused", b.get("state").asText(), b.toString());
            assertTrue(b.get("events").toString().contains("waiting for gauze, held by task " + first), b.toString());
            assertTrue(b.get("reason").asText().contains("Delivered(gauze, ward1) holds now"), b.toString());
            assertEquals(1, picks(a) + picks(b) + picks(c), "the gauze was picked up once");

            JsonNode after = JSON.readTree(api.get("/api/building"));
            assertEquals(1, count(after.get("layout").get("items"), "gauze"), "still one gauze, now in ward 1: " + after);
            assertEquals(1, count(after.get("layout").get("people"), "alice"), after.toString());
        }
    }

    private static long submit(ApiClient api, String task, String args) throws Exception {
        return JSON.readTree(api.post("/api/tasks", "{\"task\": \"" + task + "\", \"args\": " + args + "}")).get("id").asLong();
    }

    private static JsonNode await(ApiClient api, long id) throws Exception {
        long end = System.nanoTime() + TASK_MILLIS * 1_000_000L;
        JsonNode t;
        do {
            t = JSON.readTree(api.get("/api/tasks/" + id));
            if (List.of("completed", "refused", "aborted").contains(t.get("state").asText())) {
                return t;
            }
            Thread.sleep(200);
        } while (System.nanoTime() < end);
        fail("task " + id + " did not end within " + TASK_MILLIS / 1000 + " s: " + t);
        return t;
    }

    private static int picks(JsonNode task) {
        int n = 0;
        for (JsonNode e : task.get("events")) {
            if (e.get("kind").asText().equals("action_succeeded") && e.get("text").asText().contains("pick(gauze")) {
                n++;
            }
        }
        return n;
    }

    private static int count(JsonNode marks, String name) {
        int n = 0;
        for (JsonNode m : marks) {
            if (m.get("name").asText().equals(name)) {
                n++;
            }
        }
        return n;
    }
}
