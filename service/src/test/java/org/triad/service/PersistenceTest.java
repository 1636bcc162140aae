package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.store.TaskState;

import com.fasterxml.jackson.databind.JsonNode;

/** Restarting the service on the same database loses no task: queued tasks stay queued, a running one is interrupted and re-planned. */
class PersistenceTest {
    @TempDir
    Path dir;

    @Test
    void aRestartKeepsEveryTaskAndReplansTheOneThatWasRunning() throws Exception {
        Path db = dir.resolve("tasks");
        TriadService.Options slow = new TriadService.Options(ServiceFixture.HOSPITAL, List.of("dry:1,state=Morning,delay=400"), null, db, null,
                "127.0.0.1", 0, Map.of());
        long patrol;
        long queued;
        String submitToken;
        String operatorToken;
        try (TriadService first = TriadService.start(slow)) {
            assertTrue(first.tokens().generated(), "no token configured: both are generated on first start");
            submitToken = first.tokens().submitToken();
            operatorToken = first.tokens().operatorToken();
            JsonNode body = ServiceFixture.JSON.createObjectNode().put("task", "Patrol")
                    .set("args", ServiceFixture.JSON.createObjectNode().put("a", "ward2").put("b", "storage").put("c", "ward1"));
            patrol = first.fleet().submit(body).id();
            queued = first.fleet().submit(ServiceFixture.JSON.createObjectNode().put("task", "GoTo")
                    .set("args", ServiceFixture.JSON.createObjectNode().put("dst", "xray"))).id();
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (first.fleet().task(patrol).orElseThrow().events().stream().noneMatch(e -> e.kind().equals("action_succeeded"))) {
                assertTrue(System.nanoTime() < deadline, "the patrol started moving");
                ServiceFixture.sleep(20);
            }
            assertEquals("running", first.fleet().task(patrol).orElseThrow().state());
            assertEquals("queued", first.fleet().task(queued).orElseThrow().state());

            // another process finds the database locked (NAME.db.lock)
            Process probe = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                    System.getProperty("java.class.path"), LockProbe.class.getName(), db.toString()).redirectErrorStream(true).start();
            String said = new String(probe.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).strip();
            assertEquals(2, probe.waitFor(), said);
            assertTrue(said.endsWith("in use by another process (is another 'triad serve' running on it?)"), said);
        }

        TriadService.Options fast = new TriadService.Options(ServiceFixture.HOSPITAL, List.of("dry:1,state=Morning"), null, db, null, "127.0.0.1", 0,
                Map.of());
        try (TriadService second = TriadService.start(fast)) {
            assertFalse(second.tokens().generated(), "the tokens of the first start are kept");
            assertEquals(submitToken, second.tokens().submitToken());
            assertEquals(operatorToken, second.tokens().operatorToken());
            for (long id : new long[] { patrol, queued }) {
                long deadline = System.nanoTime() + 30_000_000_000L;
                while (!second.fleet().task(id).orElseThrow().state().equals("completed")) {
                    assertTrue(System.nanoTime() < deadline, "task " + id + " completes after the restart: " + second.fleet().task(id));
                    ServiceFixture.sleep(20);
                }
            }
            List<String> kinds = second.fleet().task(patrol).orElseThrow().events().stream().map(Views.EventView::kind).toList();
            int interrupted = kinds.indexOf("interrupted");
            assertTrue(interrupted > kinds.indexOf("action_succeeded"), kinds.toString());
            assertEquals("dispatched", kinds.get(interrupted + 1), "queued again and dispatched: " + kinds);
            assertEquals("task_completed", kinds.get(kinds.size() - 1));
            assertTrue(second.fleet().task(patrol).orElseThrow().events().get(interrupted).text().contains("re-planned from the robot's current state"));
            assertEquals(2, second.fleet().tasks(TaskState.COMPLETED, 10).size());
        }
    }
}
