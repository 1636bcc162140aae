package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.triad.service.Views.LiveEvent;

/**
 * The live event stream's fan-out: a client whose connection blocks (it never reads) delays nobody, and is
 * dropped once it falls a queue behind; the number of clients is bounded.
 */
class EventStreamsTest {
    /** A connection whose writes block until it is closed, as a socket whose reader stopped reading. */
    private static final class StalledSink implements EventStreams.Sink {
        final CountDownLatch closed = new CountDownLatch(1);

        @Override
        public void send(String type, Object data) throws InterruptedException {
            closed.await();
            throw new InterruptedException("closed");
        }

        @Override
        public void close() {
            closed.countDown();
        }
    }

    private static final class RecordingSink implements EventStreams.Sink {
        final List<String> got = new CopyOnWriteArrayList<>();

        @Override
        public void send(String type, Object data) {
            got.add(type + ":" + data);
        }

        @Override
        public void close() {
        }
    }

    @Test
    void aStalledClientDelaysNobodyAndIsDropped() throws Exception {
        List<String> log = new CopyOnWriteArrayList<>();
        EventStreams streams = new EventStreams(log::add);
        StalledSink stalled = new StalledSink();
        RecordingSink live = new RecordingSink();
        streams.open("stalled", stalled, new LiveEvent("hello", 0));
        streams.open("live", live, new LiveEvent("hello", 0));
        // events in bursts the live client keeps up with; the stalled client's queue fills meanwhile
        int bursts = 10;
        int burst = EventStreams.QUEUE / 2;
        int n = 0;
        for (int b = 0; b < bursts; b++) {
            for (int i = 0; i < burst; i++) {
                streams.publish(new LiveEvent("task", ++n)); // never blocks, whatever the stalled client does
            }
            int expected = n + 1;
            for (int wait = 0; wait < 2000 && live.got.size() < expected; wait++) {
                Thread.sleep(5);
            }
            assertEquals(expected, live.got.size(), "burst " + b + " reached the live client");
        }
        assertEquals("task:" + n, live.got.get(n));
        assertTrue(stalled.closed.await(10, TimeUnit.SECONDS), "the stalled client's connection is ended");
        assertEquals(List.of("triad serve: dropped event-stream client stalled: fell " + EventStreams.QUEUE + " events behind (not reading)"), log);
        assertEquals(1, streams.clients());
        streams.close();
    }

    @Test
    void theNumberOfClientsIsBounded() {
        EventStreams streams = new EventStreams(line -> { });
        for (int i = 0; i < EventStreams.MAX_CLIENTS; i++) {
            streams.open("c" + i, new RecordingSink(), new LiveEvent("hello", 0));
        }
        ServiceError e = assertThrows(ServiceError.class, () -> streams.open("one-too-many", new RecordingSink(), new LiveEvent("hello", 0)));
        assertEquals(503, e.httpStatus());
        assertEquals("already 64 event-stream clients (the limit); try again later", e.getMessage());
        streams.close();
        assertEquals(0, streams.clients());
    }
}
