package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The service plans each goal with the rest of its task as a lookahead (issue #22's battery, through {@code ./triad
 * serve}): a patrol whose first goal's shortest trip would strand the courier recharges first and completes; one that no
 * plan can complete from where the courier stands is refused before it moves, with the reason in the models' terms, and
 * such refusals are not held against the robot. The hospital's models, with the morning's courier on a low battery.
 */
class BatteryLookaheadTest {
    @TempDir
    Path dir;

    /** The hospital's models with the courier at {@code room} on {@code battery} percent in the Morning situation. */
    private Path hospital(String room, double battery) throws IOException {
        Path models = dir.resolve("models");
        Files.createDirectories(models);
        try (Stream<Path> files = Files.list(ServiceFixture.HOSPITAL)) {
            for (Path f : files.toList()) {
                Files.copy(f, models.resolve(f.getFileName()));
            }
        }
        Path morning = models.resolve("Morning.state");
        String s = Files.readString(morning);
        String low = s.replace("Courier.battery() == 100.0;", "Courier.battery() == " + battery + ";")
                .replace("Courier.loc() == lobby;", "Courier.loc() == " + room + ";");
        assertTrue(!low.equals(s) && low.contains("Courier.loc() == " + room + ";"), "the hospital's Morning changed its shape");
        Files.writeString(morning, low);
        return models;
    }

    private ServiceFixture start(Path models, String robot) {
        return ServiceFixture.start(new TriadService.Options(models, List.of(robot), null, dir.resolve("db"), null,
                "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, ServiceFixture.SUBMIT, AccessTokens.OPERATOR_ENV, ServiceFixture.OPERATOR)));
    }

    private static List<String> events(JsonNode task, String kind) {
        List<String> out = new ArrayList<>();
        task.get("events").forEach(e -> {
            if (e.get("kind").asText().equals(kind)) {
                out.add(e.get("text").asText());
            }
        });
        return out;
    }

    @Test
    void aPatrolWhoseFirstTripWouldStrandTheCourierRechargesFirst() throws IOException {
        // lobby (the dock) -> ward3 is 15.4 m, 7.7 % at 0.5 %/m: with 10 % the shortest trip there leaves 2.3 %, and the
        // patrol's next goal is back in the lobby
        try (ServiceFixture s = start(hospital("lobby", 10.0), "dry:1,state=Morning")) {
            long id = s.submit("Patrol", "{\"a\": \"ward3\", \"b\": \"lobby\", \"c\": \"ward3\"}");
            JsonNode done = s.awaitTask(id, t -> !List.of("queued", "running").contains(t.get("state").asText()));
            assertEquals("completed", done.get("state").asText(), done.toPrettyString());
            List<String> started = events(done, "action_started");
            assertTrue(started.get(0).contains("recharge(lobby)"), "it charges before it leaves: " + started);
        }
    }

    @Test
    void aPatrolThatCannotBeCompletedIsRefusedBeforeTheCourierMovesAndNotHeldAgainstIt() throws IOException {
        // ward1 -> xray is 15.4 m (7.7 %), back as much, every move keeps the 5 % reserve, and the dock is 37 m away: with
        // 15 % the courier reaches xray (7.3 % left) but can neither come back nor reach the dock, so the patrol cannot be
        // done, and the refusal is the lookahead's, at the second goal.
        // The courier's first 8 moves fail (two more tasks' worth of aborts, RefArc re-planning each 3 times): with the
        // refusal they would make 3 aborts in a row
        try (ServiceFixture s = start(hospital("ward1", 15.0), "dry:1,state=Morning,fail=move*" + 2 * 4)) {
            long id = s.submit("Patrol", "{\"a\": \"xray\", \"b\": \"ward1\", \"c\": \"xray\"}");
            JsonNode t = s.awaitState(id, "aborted");
            String reason = t.get("reason").asText();
            assertTrue(reason.startsWith(FleetService.REFUSED + "planning failed: IsAt(ward1) unreachable: Courier.battery() is 7.3")
                    && reason.contains("after IsAt(xray)"), reason);
            assertEquals(List.of(), events(t, "action_started"), "the courier did not move");
            JsonNode requests = s.get("/api/requests", ServiceFixture.OPERATOR).body();
            assertTrue(requests.get(0).get("reason").asText().startsWith(FleetService.REFUSED), requests.toPrettyString());

            for (int i = 1; i < FleetService.ABORTS_IN_A_ROW; i++) {
                JsonNode fault = s.awaitState(s.submit("GoTo", "{\"dst\": \"xray\"}"), "aborted");
                assertTrue(fault.get("reason").asText().contains("injected failure"), fault.toPrettyString());
            }
            JsonNode robot = s.get("/api/robots", ServiceFixture.OPERATOR).body().get(0);
            assertTrue(robot.get("online").asBoolean(), "a refusal is not the robot's fault, two faults are not three: " + robot);
        }
    }
}
