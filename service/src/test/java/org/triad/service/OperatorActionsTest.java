package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * Dispatch and the remote operator, with dry-run robots: dry-1 in the Morning situation (in the
 * lobby) whose first three picks fail, dry-2 in the Evening situation (in ward 1), dry-3 (Morning) that
 * stops answering after its first action, dry-4 in the Shortage situation (no gauze anywhere). dry-3
 * and dry-4 are offline unless a test needs them.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class OperatorActionsTest {
    @TempDir
    static Path dir;
    static ServiceFixture s;

    @BeforeAll
    static void start() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,state=Morning,fail=pick*4", "dry:1,state=Evening", "dry:1,state=Morning,gone=1",
                "dry:1,state=Morning,fail=pick*1000");
        s.post("/api/robots/dry-3/offline", "", ServiceFixture.OPERATOR);
        s.post("/api/robots/dry-4/offline", "", ServiceFixture.OPERATOR);
    }

    @AfterAll
    static void stop() {
        s.close();
    }

    @Test
    @Order(1) // before the other tests move the robots
    void aTaskGoesToTheRobotThatCanFinishItsFirstGoalSoonest() {
        JsonNode toWard1 = s.awaitState(s.submit("GoTo", "{\"dst\": \"ward1\"}"), "completed");
        assertEquals("dry-2", toWard1.get("robot").asText(), toWard1.toString());
        assertTrue(toWard1.get("events").get(1).get("text").asText().contains("dry-2: 0 actions"), toWard1.toString());
        JsonNode toLobby = s.awaitState(s.submit("GoTo", "{\"dst\": \"lobby\"}"), "completed");
        assertEquals("dry-1", toLobby.get("robot").asText(), "dry-1 stands in the lobby");
    }

    @Test
    void anAbortRaisesARequestWithItsCauseAndARetryOnTheSameRobotFinishesTheTask() {
        s.post("/api/robots/dry-2/offline", "", ServiceFixture.OPERATOR);
        try {
            long id = s.submit("Fetch", "{\"i\": \"syringe\", \"from\": \"storage\", \"to\": \"xray\"}");
            JsonNode aborted = s.awaitState(id, "aborted");
            assertEquals("dry-1", aborted.get("robot").asText(), aborted.toString());
            JsonNode requests = s.get("/api/requests", ServiceFixture.OPERATOR).body();
            JsonNode request = null;
            for (JsonNode r : requests) {
                if (r.get("task").asLong() == id) {
                    request = r;
                }
            }
            assertTrue(request != null, requests.toString());
            assertEquals("Holds(syringe)", request.get("goal").asText());
            assertTrue(request.get("reason").asText().contains("injected failure"), request.toString());

            JsonNode retried = s.post("/api/tasks/" + id + "/retry", "", ServiceFixture.OPERATOR).body();
            assertTrue(retried.get("events").toString().contains("retried by the operator on dry-1"), retried.toString());
            JsonNode done = s.awaitState(id, "completed");
            assertEquals("dry-1", done.get("robot").asText());
            for (JsonNode r : s.get("/api/requests", ServiceFixture.OPERATOR).body()) {
                assertTrue(r.get("task").asLong() != id, "the request is resolved");
            }
            assertEquals(409, s.post("/api/tasks/" + id + "/retry", "", ServiceFixture.OPERATOR).status(), "a completed task cannot be retried");
        } finally {
            s.post("/api/robots/dry-2/online", "", ServiceFixture.OPERATOR);
        }
    }

    @Test
    void aRobotThatVanishesMidTaskLeavesTheTaskToTheOperatorWhoReassignsIt() {
        s.post("/api/robots/dry-1/offline", "", ServiceFixture.OPERATOR);
        s.post("/api/robots/dry-2/offline", "", ServiceFixture.OPERATOR);
        s.post("/api/robots/dry-3/online", "", ServiceFixture.OPERATOR);
        long id;
        try {
            id = s.submit("Patrol", "{\"a\": \"ward2\", \"b\": \"xray\", \"c\": \"storage\"}");
            JsonNode aborted = s.awaitState(id, "aborted");
            assertEquals("dry-3", aborted.get("robot").asText());
            assertTrue(aborted.get("reason").asText().contains("does not answer"), aborted.toString());
        } finally {
            s.post("/api/robots/dry-3/offline", "", ServiceFixture.OPERATOR);
            s.post("/api/robots/dry-1/online", "", ServiceFixture.OPERATOR);
            s.post("/api/robots/dry-2/online", "", ServiceFixture.OPERATOR);
        }
        assertEquals(422, s.post("/api/tasks/" + id + "/reassign", "{\"robot\": \"dry-9\"}", ServiceFixture.OPERATOR).status());
        assertEquals(409, s.post("/api/tasks/" + id + "/reassign", "{\"robot\": \"dry-3\"}", ServiceFixture.OPERATOR).status(), "dry-3 is offline");
        JsonNode reassigned = s.post("/api/tasks/" + id + "/reassign", "{\"robot\": \"dry-2\"}", ServiceFixture.OPERATOR).body();
        assertTrue(reassigned.get("events").toString().contains("re-assigned by the operator to dry-2"), reassigned.toString());
        assertEquals("dry-2", s.awaitState(id, "completed").get("robot").asText());
    }

    @Test
    void theOperatorCanMarkAnAbortedTaskDoneOrCancelIt() {
        s.post("/api/robots/dry-1/offline", "", ServiceFixture.OPERATOR);
        s.post("/api/robots/dry-2/offline", "", ServiceFixture.OPERATOR);
        s.post("/api/robots/dry-4/online", "", ServiceFixture.OPERATOR);
        long first;
        long second;
        try {
            first = s.submit("CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward3\"}");
            second = s.submit("CollectAndDeliver", "{\"i\": \"gauze\", \"from\": \"storage\", \"to\": \"ward2\"}");
            JsonNode aborted = s.awaitState(first, "aborted");
            assertEquals("dry-4", aborted.get("robot").asText());
            s.awaitState(second, "aborted");
        } finally {
            s.post("/api/robots/dry-4/offline", "", ServiceFixture.OPERATOR);
            s.post("/api/robots/dry-1/online", "", ServiceFixture.OPERATOR);
            s.post("/api/robots/dry-2/online", "", ServiceFixture.OPERATOR);
        }
        assertEquals("done", s.post("/api/tasks/" + first + "/done", "", ServiceFixture.OPERATOR).body().get("state").asText());
        assertEquals("cancelled", s.delete("/api/tasks/" + second, ServiceFixture.OPERATOR).body().get("state").asText());
        assertEquals(409, s.delete("/api/tasks/" + first, ServiceFixture.OPERATOR).status(), "a finished task cannot be cancelled");
        assertEquals(0, s.get("/api/requests", ServiceFixture.OPERATOR).body().size(), "both requests are resolved");
        JsonNode all = s.get("/api/requests?all=true", ServiceFixture.OPERATOR).body();
        assertTrue(all.toString().contains("\"resolution\":\"done\"") && all.toString().contains("\"resolution\":\"cancelled\""), all.toString());
    }

    @Test
    void aQueuedTaskCanBeCancelledByStaff() {
        for (String r : new String[] { "dry-1", "dry-2" }) {
            s.post("/api/robots/" + r + "/offline", "", ServiceFixture.OPERATOR);
        }
        try {
            long id = s.submit("GoTo", "{\"dst\": \"xray\"}");
            assertEquals("queued", s.task(id).get("state").asText(), s.task(id).toString() + s.get("/api/robots", ServiceFixture.SUBMIT).body());
            JsonNode cancelled = s.delete("/api/tasks/" + id, ServiceFixture.SUBMIT).body();
            assertEquals("cancelled", cancelled.get("state").asText());
            assertTrue(cancelled.get("reason").asText().contains("staff"));
        } finally {
            for (String r : new String[] { "dry-1", "dry-2" }) {
                s.post("/api/robots/" + r + "/online", "", ServiceFixture.OPERATOR);
            }
        }
    }
}
