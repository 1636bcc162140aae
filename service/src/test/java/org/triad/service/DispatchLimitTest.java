package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * {@code dispatch.atOnce} in the application's {@code application.properties}: at most that many robots run a task at
 * once, the others stay idle until one is done; every task still runs. Dry-run robots whose actions take a while.
 */
class DispatchLimitTest {
    @TempDir
    Path dir;

    private <T> T withProperties(String properties, Supplier<T> start) throws Exception {
        Path app = dir.resolve("app");
        Files.createDirectories(app.resolve("META-INF/triad"));
        Files.writeString(app.resolve(ChargingPolicy.RESOURCE), properties);
        Thread t = Thread.currentThread();
        ClassLoader before = t.getContextClassLoader();
        try (URLClassLoader loader = new URLClassLoader(new URL[] { app.toUri().toURL() }, before)) {
            t.setContextClassLoader(loader);
            return start.get();
        } finally {
            t.setContextClassLoader(before);
        }
    }

    @Test
    void atMostTwoOfThreeRobotsRunATaskAtOnceAndEveryTaskIsRunOnOne() throws Exception {
        try (ServiceFixture s = withProperties("dispatch.atOnce=2\n", () -> ServiceFixture.start(dir.resolve("db"), "dry:3,delay=100"))) {
            List<Long> ids = new ArrayList<>();
            for (String room : List.of("ward1", "ward2", "ward3", "xray")) {
                ids.add(s.submit("GoTo", "{\"dst\": \"" + room + "\"}"));
            }
            int most = 0;
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (true) {
                int running = 0;
                int ended = 0;
                for (JsonNode t : s.get("/api/tasks", ServiceFixture.SUBMIT).body()) {
                    running += t.path("state").asText().equals("running") ? 1 : 0;
                    ended += List.of("completed", "aborted", "refused").contains(t.path("state").asText()) && !t.path("robot").isNull() ? 1 : 0;
                }
                most = Math.max(most, running);
                if (ended == ids.size()) {
                    break;
                }
                assertTrue(System.nanoTime() < deadline, "the tasks did not all complete: " + s.get("/api/tasks", ServiceFixture.SUBMIT).body());
                Thread.sleep(10);
            }
            assertEquals(2, most, "two robots at once, never three");
        }
    }

    @Test
    void aLimitThatIsNoNumberOfRobotsStopsTheStartWithTheReason() throws Exception {
        ServiceError e = assertThrows(ServiceError.class, () -> withProperties("dispatch.atOnce=none\n",
                () -> ServiceFixture.start(dir.resolve("db"), "dry:1")));
        // the file is named where it was found, as for the charging policy
        assertEquals(dir.resolve("app").resolve(ChargingPolicy.RESOURCE).toUri().toURL() + ": dispatch.atOnce takes a whole number of robots, at least 1, not 'none'",
                e.getMessage());
    }
}
