package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/** A robot whose tasks keep aborting is taken out of dispatch with the reason shown to the operator; the others take the work. */
class FaultyRobotTest {
    @TempDir
    Path dir;
    ServiceFixture s;

    @AfterEach
    void stop() {
        if (s != null) {
            s.close();
        }
    }

    private JsonNode robot(String name) {
        for (JsonNode r : s.get("/api/robots", ServiceFixture.OPERATOR).body()) {
            if (r.get("name").asText().equals(name)) {
                return r;
            }
        }
        throw new AssertionError("no robot " + name);
    }

    @Test
    void aRobotOnWhichThreeTasksInARowAbortedIsTakenOutOfDispatchWithTheReason() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,fail=move*1000", "dry:1");
        s.post("/api/robots/dry-2/offline", "", ServiceFixture.OPERATOR);
        for (int i = 0; i < FleetService.ABORTS_IN_A_ROW; i++) {
            JsonNode aborted = s.awaitState(s.submit("GoTo", "{\"dst\": \"xray\"}"), "aborted");
            assertEquals("dry-1", aborted.get("robot").asText());
        }
        JsonNode out = robot("dry-1");
        assertFalse(out.get("online").asBoolean(), out.toString());
        String reason = out.get("offlineReason").asText();
        assertTrue(reason.contains("taken out of dispatch: 3 tasks in a row aborted on it") && reason.contains("injected failure"), reason);

        s.post("/api/robots/dry-2/online", "", ServiceFixture.OPERATOR);
        JsonNode done = s.awaitState(s.submit("GoTo", "{\"dst\": \"xray\"}"), "completed");
        assertEquals("dry-2", done.get("robot").asText(), "the faulty robot gets no more work");

        s.post("/api/robots/dry-1/online", "", ServiceFixture.OPERATOR);
        assertTrue(robot("dry-1").get("online").asBoolean(), "the operator puts it back");
        assertTrue(robot("dry-1").get("offlineReason").isNull());
    }
}
