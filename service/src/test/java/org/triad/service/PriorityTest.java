package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/** Task priority: higher first, first come first served within a priority; in the API and the OpenAPI document. */
class PriorityTest {
    @TempDir
    Path dir;
    ServiceFixture s;

    @AfterEach
    void stop() {
        if (s != null) {
            s.close();
        }
    }

    private long submit(String room, int priority) {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"" + room + "\"}, \"priority\": " + priority + "}",
                ServiceFixture.SUBMIT);
        assertEquals(201, r.status(), r.body().toString());
        assertEquals(priority, r.body().get("priority").asInt());
        return r.body().get("id").asLong();
    }

    private long dispatchedAt(long id) {
        for (JsonNode e : s.awaitState(id, "completed").get("events")) {
            if (e.get("kind").asText().equals("dispatched")) {
                return e.get("id").asLong();
            }
        }
        throw new AssertionError("task " + id + " was not dispatched");
    }

    @Test
    void higherPriorityFirstAndFirstComeFirstServedWithin() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,state=Morning");
        s.post("/api/robots/dry-1/offline", "", ServiceFixture.OPERATOR);
        long low = submit("xray", 0);
        long high = submit("ward1", 5);
        long highToo = submit("ward2", 5);
        long urgent = submit("ward3", 9);
        s.post("/api/robots/dry-1/online", "", ServiceFixture.OPERATOR);
        List<Long> order = List.of(low, high, highToo, urgent).stream().sorted(Comparator.comparingLong(this::dispatchedAt)).toList();
        assertEquals(List.of(urgent, high, highToo, low), order);
    }

    @Test
    void queuedAndRunningTasksShowAnExpectedStartAndFinishOnceATaskHasCompleted() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,state=Morning,delay=100");
        long first = submit("xray", 0);
        assertTrue(s.task(first).path("expectedStart").isNull(), "nothing to go by before a task completed");
        s.awaitState(first, "completed");
        s.post("/api/robots/dry-1/offline", "", ServiceFixture.OPERATOR);
        long a = submit("ward1", 0);
        long b = submit("ward2", 0);
        assertTrue(s.task(a).path("expectedStart").isNull(), "no robot online, no expected start");
        s.post("/api/robots/dry-1/online", "", ServiceFixture.OPERATOR);
        JsonNode earlier = s.task(a); // read first: an expectation in the past moves to 'now'
        JsonNode later = s.task(b);
        if (later.get("state").asText().equals("queued") && !earlier.path("expectedFinish").isNull()) {
            java.time.Instant aFinish = java.time.Instant.parse(earlier.get("expectedFinish").asText());
            java.time.Instant bStart = java.time.Instant.parse(later.get("expectedStart").asText());
            assertTrue(!bStart.isBefore(aFinish.minusMillis(1)), "the second starts when the first is expected to finish: " + earlier + later);
            assertTrue(java.time.Instant.parse(later.get("expectedFinish").asText()).isAfter(bStart));
        }
        s.awaitState(b, "completed");
        assertTrue(s.task(b).path("expectedStart").isNull(), "a finished task has no expectation");
    }

    @Test
    void aPriorityOutOfRangeIsAFieldErrorAndTheOpenApiDocumentHasIt() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,state=Morning");
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"xray\"}, \"priority\": 1000}", ServiceFixture.SUBMIT);
        assertEquals(422, r.status(), r.body().toString());
        assertTrue(r.body().toString().contains("\"priority\"") && r.body().toString().contains("from -100 to 100"), r.body().toString());
        JsonNode doc = s.get("/api/openapi.json", ServiceFixture.SUBMIT).body();
        assertEquals(100, doc.at("/components/schemas/Task/properties/priority/maximum").asInt(), doc.at("/components/schemas/Task").toString());
        assertEquals(0, doc.at("/components/schemas/Task.GoTo/properties/priority/default").asInt(-1), doc.at("/components/schemas/Task.GoTo").toString());
    }
}
