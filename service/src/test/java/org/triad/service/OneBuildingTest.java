package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * One building, many robots, through the service: the fleet's robots share one world, a task whose
 * objects another running task holds waits, and one gauze is delivered once however often it is asked for.
 */
class OneBuildingTest {
    @TempDir
    Path dir;
    ServiceFixture s;

    @AfterEach
    void stop() {
        if (s != null) {
            s.close();
        }
    }

    private static boolean ended(JsonNode t) {
        return List.of("completed", "refused", "aborted").contains(t.get("state").asText());
    }

    @Test
    void threeRequestsForOneGauzeOnThreeRobotsDeliverItOnceTheOthersAreRefusedWithTheReason() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:3,state=Morning,delay=30");
        List<Long> ids = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            ids.add(s.submit("CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward1\"}"));
        }
        List<JsonNode> done = ids.stream().map(id -> s.awaitTask(id, OneBuildingTest::ended)).toList();
        assertEquals("completed", done.get(0).get("state").asText(), done.get(0).toString());
        int picks = 0;
        for (JsonNode t : done) {
            for (JsonNode e : t.get("events")) {
                if (e.get("kind").asText().equals("action_succeeded") && e.get("text").asText().contains("pick(gauze")) {
                    picks++;
                }
            }
        }
        assertEquals(1, picks, "the gauze was picked up once: " + done);
        for (JsonNode t : done.subList(1, 3)) {
            assertEquals("refused", t.get("state").asText(), t.toString());
            String events = t.get("events").toString();
            assertTrue(events.contains("waiting for gauze, held by task " + ids.get(0) + " on dry-"), events);
            assertTrue(t.get("reason").asText().contains("Delivered(gauze, ward1) holds now"), t.toString());
            assertTrue(t.get("robot") == null || t.get("robot").isNull(), "no robot executed it: " + t);
        }
    }

    @Test
    void whatOneRobotPicksUpIsGoneForTheOthersAndAWaitingTaskThatStillMattersRunsFromTheWorldAsItIsNow() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:2,state=Morning,delay=30");
        long first = s.submit("CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward1\"}");
        long second = s.submit("Deliver", "{\"i\": \"gauze\", \"to\": \"ward3\"}");
        long other = s.submit("GoTo", "{\"dst\": \"xray\"}");
        JsonNode a = s.awaitState(first, "completed");
        JsonNode b = s.awaitState(second, "completed");
        s.awaitState(other, "completed");
        assertTrue(b.get("events").toString().contains("waiting for gauze, held by task " + first), b.toString());
        assertTrue(b.get("events").toString().contains("pick(gauze, ward1)"), "fetched from where the first task left it: " + b);
        assertTrue(a.get("events").toString().contains("pick(gauze, storage)"), a.toString());
    }
}
