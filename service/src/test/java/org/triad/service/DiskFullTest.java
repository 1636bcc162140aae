package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * A full disk, then room again: the database lives on a 4 MB tmpfs that the test fills. While it is
 * full, submissions answer 503 with the cause and the robot's reports wait; once the filler is deleted
 * the service works again without a restart, the running task completes, and /api/health tells the
 * operator what happened. Mounting needs root (or sudo without password, as on CI runners).
 */
class DiskFullTest {
    private static final String PATROL = "{\"a\": \"ward2\", \"b\": \"storage\", \"c\": \"ward1\"}";

    @Test
    void aFullDiskHealsWithoutARestartOnceThereIsRoomAgain() throws Exception {
        Path mount = Files.createTempDirectory("triad-disk");
        sh(List.of("mount", "-t", "tmpfs", "-o", "size=4m,mode=0777", "tmpfs", mount.toString()));
        try (ServiceFixture f = ServiceFixture.start(mount.resolve("tasks"), "dry:1,state=Morning,delay=300")) {
            long patrol = f.submit("Patrol", PATROL);
            f.awaitTask(patrol, t -> PostgresFailoverTest.kinds(t).contains("action_started"));

            Path filler = mount.resolve("filler");
            try (OutputStream out = Files.newOutputStream(filler)) {
                byte[] block = new byte[16 * 1024];
                while (true) {
                    out.write(block);
                }
            } catch (IOException full) {
                assertTrue(String.valueOf(full.getMessage()).contains("No space left on device"), full.toString());
            }
            ServiceFixture.Response refused = f.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"xray\"}}", ServiceFixture.SUBMIT);
            assertEquals(503, refused.status(), String.valueOf(refused.body()));
            assertEquals("database-unavailable", refused.body().get("error").asText());
            assertTrue(refused.body().get("message").asText().contains("full"), refused.body().toString());
            JsonNode failing = f.get("/api/health", ServiceFixture.OPERATOR).body();
            assertEquals(false, failing.get("ok").asBoolean(), failing.toString());

            Files.delete(filler);
            long after = f.submit("GoTo", "{\"dst\": \"xray\"}");
            f.awaitState(patrol, "completed");
            f.awaitState(after, "completed");
            JsonNode healed = f.get("/api/health", ServiceFixture.OPERATOR).body();
            assertTrue(healed.get("ok").asBoolean(), healed.toString());
            String outage = healed.get("outages").get(0).asText();
            assertTrue(outage.contains("full") && outage.contains("it works again"), outage);
        } finally {
            sh(List.of("umount", "-l", mount.toString()));
            Files.deleteIfExists(mount);
        }
    }

    private static void sh(List<String> command) throws IOException, InterruptedException {
        List<String> c = new ArrayList<>();
        if (!"root".equals(System.getProperty("user.name"))) {
            c.addAll(List.of("sudo", "-n"));
        }
        c.addAll(command);
        Process p = new ProcessBuilder(c).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        p.waitFor(60, TimeUnit.SECONDS);
        if (p.exitValue() != 0) {
            throw new AssertionError(c + " failed (the disk-full test mounts a small tmpfs: it needs root or sudo without password): " + out);
        }
    }
}
