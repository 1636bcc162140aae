package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The embedded database under SIGKILL (a power cut, the OOM killer): a real service process is killed
 * right after a 201 while other submissions are in flight, six times in a row on the same file. Every
 * start succeeds and every acknowledged task is there with its id and its arguments.
 */
class CrashSafetyTest {
    private static final String[] ROOMS = { "xray", "ward1", "ward2", "storage" };
    private static final int KILLS = 6;

    @TempDir
    Path dir;

    /**
     * Six kills (the suite's time is short; each kill lands at a random point among other commits, and the file is opened
     * afresh seven times): every start succeeds and every acknowledged task is there. A submission with an idempotency key
     * stored before the first kill and repeated after it (the client lost the answer) finds the stored task.
     */
    @Test
    void killsRightAfterA201LoseNoAcknowledgedTaskAndEveryStartSucceeds() throws Exception {
        String db = dir.resolve("tasks").toString();
        Map<Long, String> acknowledged = new ConcurrentHashMap<>();
        Random random = new Random(26);
        long keyed = -1;
        try (ServiceProcesses processes = new ServiceProcesses()) {
            for (int round = 0; round <= KILLS; round++) {
                ServiceProcesses.Running service = processes.startOrFail(db, "dry:2,state=Morning");
                for (Map.Entry<Long, String> e : acknowledged.entrySet()) {
                    ServiceFixture.Response r = processes.get(service.url(), "/api/tasks/" + e.getKey());
                    assertEquals(200, r.status(), "round " + round + ": acknowledged task " + e.getKey() + " is there after the kill");
                    assertEquals("GoTo", r.body().get("task").asText());
                    assertEquals(e.getValue(), r.body().get("args").get("dst").asText(), "task " + e.getKey() + " keeps its id: " + r.body());
                }
                if (round == 0) {
                    ServiceFixture.Response stored = processes.submit(service.url(), "GoTo", "{\"dst\": \"pharmacy\"}", "ward-3-request-17");
                    assertEquals(201, stored.status(), String.valueOf(stored.body()));
                    keyed = stored.body().get("id").asLong();
                } else if (round == 1) {
                    ServiceFixture.Response again = processes.submit(service.url(), "GoTo", "{\"dst\": \"pharmacy\"}", "ward-3-request-17");
                    assertEquals(200, again.status(), "the client lost the first answer and asks again: " + again.body());
                    assertEquals(keyed, again.body().get("id").asLong(), "the stored task, not a second one: " + again.body());
                    ServiceFixture.Response other = processes.submit(service.url(), "GoTo", "{\"dst\": \"ward1\"}", "ward-3-request-17");
                    assertEquals(422, other.status(), String.valueOf(other.body()));
                    assertEquals("idempotency-key-reused", other.body().get("error").asText());
                }
                if (round == KILLS) {
                    break;
                }
                // a second client keeps submitting, so that the kill lands among other commits
                AtomicBoolean killed = new AtomicBoolean();
                AtomicInteger n = new AtomicInteger(round * 1000);
                Thread other = new Thread(() -> {
                    while (!killed.get()) {
                        submit(processes, service, n.incrementAndGet(), acknowledged);
                    }
                });
                other.start();
                int killAfter = 5 + random.nextInt(30);
                for (int i = 0; i < killAfter;) {
                    if (submit(processes, service, n.incrementAndGet(), acknowledged)) {
                        i++;
                    }
                }
                // right after the 201 of the last one
                killed.set(true);
                service.kill();
                other.join(60_000);
            }
        }
        assertTrue(acknowledged.size() >= 30, "tasks acknowledged: " + acknowledged.size());
    }

    private static boolean submit(ServiceProcesses processes, ServiceProcesses.Running service, int n, Map<Long, String> acknowledged) {
        String room = ROOMS[n % ROOMS.length];
        ServiceFixture.Response r = processes.submit(service.url(), "GoTo", "{\"dst\": \"" + room + "\"}");
        if (r.status() == 201) {
            JsonNode body = r.body();
            String before = acknowledged.putIfAbsent(body.get("id").asLong(), room);
            assertEquals(null, before, "id " + body.get("id") + " given twice");
            return true;
        }
        return false;
    }
}
