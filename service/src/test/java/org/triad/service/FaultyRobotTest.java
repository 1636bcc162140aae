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

    /** Traffic control's words for a jam (as the mixed benchmark's aborts gave them) do not count against the robot; a fault does. */
    @Test
    void anAbortThatIsTheBuildingsCongestionDoesNotCountAgainstTheRobot() {
        assertTrue(FleetService.congestion("task GoTo(xray) aborted at goal IsAt(xray): action Courier.move(lobby, c4) failed: the platform"
                + " reported failure: drive lobby -> c4 failed on AGV triad/courier-5: triad/courier-5 waits at lobby for node 'c4' (held by"
                + " or promised to triad/courier-2) for more than 120.0 s (the wait bound)"));
        assertTrue(FleetService.congestion("action Courier.move(c6, c3) failed: the platform reported failure: drive c6 -> c3 on AGV"
                + " triad/courier-8 refused by traffic control: deadlock avoided: triad/courier-8 would wait for triad/courier-4 (node 'c3')"));
        assertFalse(FleetService.congestion("action Courier.move(c4, c5) failed: the platform reported failure: PATH_BLOCKED"));
        assertFalse(FleetService.congestion("drive c4 -> c5 on AGV triad/courier-1 refused by traffic control: the robot stands at 'c1' on the traffic map"),
                "a robot the traffic map has elsewhere is the robot's own trouble");
        assertFalse(FleetService.congestion("injected failure 1 of 1000 (fail=move*1000)"));
    }
}
