package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.Views.LiveEvent;

/**
 * The attack on the live event stream, over real sockets: one client opens {@code /api/events}
 * and never reads (a raw socket with a small receive buffer, which fills as a stalled browser tab's
 * does), while another reads (Java's HTTP client). Events published meanwhile reach the reading client within a second (the median of
 * every event's delay from publication to receipt, measured in this JVM; the issue saw 22-80 s), and
 * the stalled client is dropped once it falls a queue behind.
 */
class StalledEventClientTest {
    private static final int MAX_EVENTS = 3000;
    /** Each event carries 8 KB, so the stalled connection's buffers fill after a few dozen events. */
    private static final String PAD = "x".repeat(8 << 10);
    private static final Pattern SEQ = Pattern.compile("\"seq\":(\\d+)");

    @TempDir
    Path dir;

    @Test
    void aClientThatStopsReadingDelaysNobodyAndIsDropped() throws Exception {
        try (ServiceFixture s = ServiceFixture.start(dir.resolve("db"));
                Socket stalled = new Socket()) {
            EventStreams streams = s.service.events();
            stalled.setReceiveBufferSize(4096);
            stalled.connect(new InetSocketAddress("127.0.0.1", s.service.port()), 10_000);
            subscribe(stalled);
            AtomicLongArray received = new AtomicLongArray(MAX_EVENTS);
            HttpClient http = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1).connectTimeout(Duration.ofSeconds(10)).build();
            HttpRequest events = HttpRequest.newBuilder(URI.create(s.service.url() + "/api/events?token=" + ServiceFixture.SUBMIT))
                    .header("Accept", "text/event-stream").build();
            Stream<String> lines = http.send(events, HttpResponse.BodyHandlers.ofLines()).body();
            Thread reader = new Thread(() -> read(lines, received), "live-events");
            reader.setDaemon(true);
            reader.start();
            for (int i = 0; i < 2000 && streams.clients() < 2; i++) {
                Thread.sleep(10);
            }
            assertEquals(2, streams.clients(), "both clients are subscribed");

            long[] published = new long[MAX_EVENTS];
            int n = 0;
            int afterDrop = 0;
            while (n < MAX_EVENTS && afterDrop < 50) {
                published[n] = System.nanoTime();
                Map<String, Object> data = new LinkedHashMap<>();
                data.put("seq", n);
                data.put("pad", PAD);
                streams.publish(new LiveEvent("probe", data));
                n++;
                if (streams.clients() < 2) {
                    afterDrop++;
                }
                Thread.sleep(5);
            }
            assertEquals(1, streams.clients(), "the stalled client was dropped after " + n + " events");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (received.get(n - 1) == 0 && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            long[] delays = new long[n];
            for (int i = 0; i < n; i++) {
                assertTrue(received.get(i) != 0, "event " + i + " of " + n + " reached the reading client");
                delays[i] = received.get(i) - published[i];
            }
            Arrays.sort(delays);
            double medianMs = delays[n / 2] / 1e6;
            assertTrue(medianMs < 1000, "median delay " + medianMs + " ms over " + n + " events (90th percentile "
                    + delays[n * 9 / 10] / 1e6 + " ms)");
        }
    }

    private static void subscribe(Socket socket) throws IOException {
        OutputStream out = socket.getOutputStream();
        out.write(("GET /api/events?token=" + ServiceFixture.SUBMIT + " HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept: text/event-stream\r\n\r\n")
                .getBytes(StandardCharsets.US_ASCII));
        out.flush();
    }

    /** Notes when each probe event's data line arrives. */
    private static void read(Stream<String> lines, AtomicLongArray received) {
        try {
            lines.filter(line -> line.startsWith("data:")).forEach(line -> {
                Matcher m = SEQ.matcher(line);
                if (m.find()) {
                    int seq = Integer.parseInt(m.group(1));
                    if (seq < received.length()) {
                        received.compareAndSet(seq, 0, System.nanoTime());
                    }
                }
            });
        } catch (RuntimeException e) {
            // the service closed the stream at the end of the test
        }
    }
}
