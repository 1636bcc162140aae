package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The request limits on a running service: each refused with a 4xx naming the limit, the body while it is read. */
class RequestLimitsTest {
    @TempDir
    static Path dir;
    private static ServiceFixture s;

    @BeforeAll
    static void start() {
        s = ServiceFixture.start(dir.resolve("db"), "dry:1");
    }

    @AfterAll
    static void stop() {
        s.close();
    }

    @Test
    void a300MiBChunkedBodyIsRefusedWithinTheFirstMiB() throws Exception {
        URI u = URI.create(s.service.url());
        try (Socket socket = new Socket(u.getHost(), u.getPort())) {
            socket.setSoTimeout(60_000);
            OutputStream out = socket.getOutputStream();
            out.write(("POST /api/tasks HTTP/1.1\r\nHost: " + u.getHost() + "\r\nAuthorization: Bearer " + ServiceFixture.SUBMIT
                    + "\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
            // announce a 300 MiB body, send its first MiB, and wait: a server that reads bodies whole before judging never answers
            byte[] chunk = new byte[64 * 1024];
            java.util.Arrays.fill(chunk, (byte) '[');
            Thread writer = new Thread(() -> {
                try {
                    for (int i = 0; i < 16; i++) {
                        out.write((Integer.toHexString(chunk.length) + "\r\n").getBytes(StandardCharsets.US_ASCII));
                        out.write(chunk);
                        out.write("\r\n".getBytes(StandardCharsets.US_ASCII));
                    }
                    out.flush();
                } catch (java.io.IOException e) {
                    // the server answered and closed the connection: what is expected
                }
            }, "chunked-writer");
            writer.setDaemon(true);
            writer.start();
            BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            String status = in.readLine();
            assertEquals("HTTP/1.1 413 Payload Too Large", status);
            StringBuilder rest = new StringBuilder();
            for (String line; (line = in.readLine()) != null;) {
                rest.append(line).append('\n');
            }
            assertTrue(rest.toString().contains("the body is larger than 65536 bytes (the body limit)"), rest.toString());
        }
    }

    @Test
    void deepNestingIsRefusedNamingTheDepthLimit() {
        ServiceFixture.Response r = s.post("/api/tasks", "[".repeat(50_000), ServiceFixture.SUBMIT);
        assertEquals(400, r.status(), String.valueOf(r.body()));
        assertEquals("limit-exceeded", r.body().get("error").asText());
        assertEquals("the body nests JSON deeper than 32 levels (the depth limit)", r.body().get("message").asText());
    }

    @Test
    void aLongNumberIsRefusedNamingTheNumberLimit() {
        ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": " + "9".repeat(60_000) + "}}",
                ServiceFixture.SUBMIT);
        assertEquals(400, r.status(), String.valueOf(r.body()));
        assertEquals("a number in the body is longer than 40 characters (the number limit)", r.body().get("message").asText());
    }

    @Test
    void aLongStringIsRefusedNamingTheStringLimit() {
        for (int n : new int[] { 1001, 20_000 }) {
            ServiceFixture.Response r = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"" + "w".repeat(n) + "\"}}",
                    ServiceFixture.SUBMIT);
            assertEquals(400, r.status(), String.valueOf(r.body()));
            assertEquals("a string in the body is longer than 1000 characters (the string limit)", r.body().get("message").asText());
        }
        // at the limit it is an ordinary unknown object
        ServiceFixture.Response ok = s.post("/api/tasks", "{\"task\": \"GoTo\", \"args\": {\"dst\": \"" + "w".repeat(1000) + "\"}}",
                ServiceFixture.SUBMIT);
        assertEquals(422, ok.status(), String.valueOf(ok.body()));
    }

    @Test
    void theEventStreamWithoutItsAcceptIs406() {
        ServiceFixture.Response r = s.get("/api/events", ServiceFixture.SUBMIT);
        assertEquals(406, r.status());
        assertEquals("/api/events is a stream of server-sent events: send 'Accept: text/event-stream'", r.body().get("message").asText());
    }
}
