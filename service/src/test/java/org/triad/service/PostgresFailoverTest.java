package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * Two service processes on one PostgreSQL server (started by the test): one dispatches, both serve the
 * API; when the dispatching one is killed (SIGKILL) with a task in flight, the other takes the lease
 * over, queues the task again, and it completes once.
 */
class PostgresFailoverTest {
    @Test
    void whenTheDispatcherIsKilledTheOtherInstanceTakesOverAndTheTaskInFlightCompletesOnce() throws Exception {
        try (PostgresServer pg = PostgresServer.start(); ServiceProcesses processes = new ServiceProcesses()) {
            ServiceProcesses.Running a = processes.startOrFail(pg.url(), "dry:1,state=Morning,delay=300");
            ServiceProcesses.Running b = processes.startOrFail(pg.url(), "dry:1,state=Morning,delay=300");
            assertTrue(processes.get(a.url(), "/api/health").body().get("dispatching").asBoolean(), "the first instance dispatches");
            JsonNode standby = processes.get(b.url(), "/api/health").body();
            assertFalse(standby.get("dispatching").asBoolean(), standby.toString());
            assertTrue(standby.get("shared").asBoolean() && standby.get("database").asText().startsWith("postgresql://triad@127.0.0.1:"), standby.toString());

            // submitted through the standby, run by the dispatcher's robot
            ServiceFixture.Response r = processes.submit(b.url(), "Patrol", "{\"a\": \"ward2\", \"b\": \"storage\", \"c\": \"ward1\"}");
            assertEquals(201, r.status(), String.valueOf(r.body()));
            long patrol = r.body().get("id").asLong();
            await(processes, b, patrol, t -> kinds(t).contains("action_succeeded"), "the patrol is under way on the first instance");
            assertEquals("running", processes.get(b.url(), "/api/tasks/" + patrol).body().get("state").asText());

            a.kill();
            long queuedMeanwhile = processes.submit(b.url(), "GoTo", "{\"dst\": \"xray\"}").body().get("id").asLong();
            JsonNode done = await(processes, b, patrol, t -> t.get("state").asText().equals("completed"), "the patrol completes after the take-over");
            List<String> kinds = kinds(done);
            assertEquals(1, kinds.stream().filter("task_completed"::equals).count(), "completed once: " + kinds);
            assertEquals(2, kinds.stream().filter("dispatched"::equals).count(), "dispatched by each instance once: " + kinds);
            int interrupted = kinds.indexOf("interrupted");
            assertTrue(interrupted > kinds.indexOf("action_succeeded") && kinds.get(interrupted + 1).equals("dispatched"), kinds.toString());
            await(processes, b, queuedMeanwhile, t -> t.get("state").asText().equals("completed"), "a task submitted during the take-over completes");

            JsonNode health = processes.get(b.url(), "/api/health").body();
            assertTrue(health.get("dispatching").asBoolean(), health.toString());
            assertTrue(health.get("lease").get(0).asText().contains("took over dispatch; 1 task(s) the previous one ran are queued again"), health.toString());
        }
    }

    @Test
    void whenTheServerCrashesAndComesBackTheServiceHealsAndTheRunningTaskCompletesOnce() throws Exception {
        try (PostgresServer pg = PostgresServer.start(); ServiceProcesses processes = new ServiceProcesses()) {
            ServiceProcesses.Running service = processes.startOrFail(pg.url(), "dry:1,state=Morning,delay=300");
            long patrol = processes.submit(service.url(), "Patrol", "{\"a\": \"ward2\", \"b\": \"storage\", \"c\": \"ward1\"}").body().get("id").asLong();
            await(processes, service, patrol, t -> kinds(t).contains("action_succeeded"), "the patrol is under way");

            pg.crashAndRestart(2000);
            JsonNode done = await(processes, service, patrol, t -> t.get("state").asText().equals("completed"), "the patrol completes after the outage");
            assertEquals(1, kinds(done).stream().filter("task_completed"::equals).count(), "completed once: " + kinds(done));
            ServiceFixture.Response r = processes.submit(service.url(), "GoTo", "{\"dst\": \"xray\"}");
            assertEquals(201, r.status(), "submissions work again without a restart: " + r.body());
            JsonNode health = processes.get(service.url(), "/api/health").body();
            assertTrue(health.get("ok").asBoolean() && health.get("dispatching").asBoolean(), health.toString());
            assertTrue(health.get("lease").get(0).asText().contains("took over dispatch; 1 task(s)"), health.toString());
            assertTrue(health.get("lease").get(1).asText().contains("lost the dispatch lease"), health.toString());
        }
    }

    static List<String> kinds(JsonNode task) {
        List<String> out = new ArrayList<>();
        task.get("events").forEach(e -> out.add(e.get("kind").asText()));
        return out;
    }

    private static JsonNode await(ServiceProcesses processes, ServiceProcesses.Running on, long id, Predicate<JsonNode> until, String what) {
        long deadline = System.nanoTime() + 90_000_000_000L;
        JsonNode t = processes.get(on.url(), "/api/tasks/" + id).body();
        while (t == null || !until.test(t)) {
            if (System.nanoTime() > deadline) {
                fail(what + ": not within 90 s: " + t + "\n" + on.output());
            }
            ServiceFixture.sleep(50);
            t = processes.get(on.url(), "/api/tasks/" + id).body();
        }
        return t;
    }
}
