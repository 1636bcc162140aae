package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

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

    /**
     * A run that the building's congestion ended (the dry robots' {@code jam=}: failures with traffic control's cause, as
     * a wait over the bound or a refusal to avoid a deadlock end a drive) queues its task again, on the same robot: the
     * next run completes, no operator is called, and it does not count against the robot.
     */
    @Test
    void aTaskThatCongestionEndedIsQueuedAgainAndCompletes() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,jam=move*4");
        s.service.fleet().congestionPause(java.time.Duration.ZERO);
        long id = s.submit("GoTo", "{\"dst\": \"xray\"}");
        JsonNode done = s.awaitState(id, "completed");
        assertEquals("dry-1", done.get("robot").asText());
        List<String> kinds = kinds(done);
        assertEquals(1, kinds.stream().filter("congestion_requeued"::equals).count(), kinds.toString());
        assertTrue(kinds.indexOf("task_aborted") < kinds.indexOf("congestion_requeued")
                && kinds.indexOf("congestion_requeued") < kinds.lastIndexOf("dispatched"), "aborted, queued again, dispatched again: " + kinds);
        assertFalse(kinds.contains("remote_operation"), "congestion calls no operator: " + kinds);
        String requeued = text(done, "congestion_requeued");
        assertTrue(requeued.contains("(1 of " + FleetService.CONGESTION_REQUEUES + ")") && requeued.contains("injected congestion 4 of 4"), requeued);
        assertEquals(0, s.get("/api/requests", ServiceFixture.OPERATOR).body().size(), "no remote-operation request");
    }

    /** A task that congestion keeps ending is queued again {@link FleetService#CONGESTION_REQUEUES} times, then ends aborted with the reason; the robot stays in dispatch. */
    @Test
    void aTaskThatCongestionKeepsEndingEndsAbortedWithTheReasonAfterTheBound() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1,jam=move*1000");
        s.service.fleet().congestionPause(java.time.Duration.ZERO);
        JsonNode aborted = s.awaitState(s.submit("GoTo", "{\"dst\": \"xray\"}"), "aborted");
        String reason = aborted.get("reason").asText();
        assertTrue(reason.contains("injected congestion") && reason.contains("queued again " + FleetService.CONGESTION_REQUEUES + " times"), reason);
        assertEquals(FleetService.CONGESTION_REQUEUES, kinds(aborted).stream().filter("congestion_requeued"::equals).count(), kinds(aborted).toString());
        assertTrue(kinds(aborted).contains("remote_operation"), "the operator decides now: " + kinds(aborted));
        JsonNode robot = robot("dry-1");
        assertTrue(robot.get("online").asBoolean(), FleetService.CONGESTION_REQUEUES + 1 + " runs ended by congestion do not take the robot out: " + robot);
    }

    private static List<String> kinds(JsonNode task) {
        List<String> out = new java.util.ArrayList<>();
        task.get("events").forEach(e -> out.add(e.get("kind").asText()));
        return out;
    }

    private static String text(JsonNode task, String kind) {
        for (JsonNode e : task.get("events")) {
            if (e.get("kind").asText().equals(kind)) {
                return e.get("text").asText();
            }
        }
        throw new AssertionError("no " + kind + " event in " + task);
    }
}
