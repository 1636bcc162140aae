package org.triad.service;

import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import org.triad.service.Views.LiveEvent;

/**
 * The clients of the live event stream, each with its own queue and its own sender thread, so that a client
 * that reads slowly or not at all delays nobody else: {@link #publish} never blocks. A client that falls
 * {@value #QUEUE} events behind is dropped (it reconnects and starts from a fresh {@code hello}); at most
 * {@value #MAX_CLIENTS} clients at once.
 */
final class EventStreams {
    static final int MAX_CLIENTS = 64;
    static final int QUEUE = 256;

    /** Where one client's events go: the SSE connection, written by its own thread. */
    interface Sink {
        /** Sends one event; may block while the client does not read. */
        void send(String type, Object data) throws Exception;

        /** Ends the client's connection (from any thread). */
        void close();
    }

    private final Set<Subscriber> subscribers = ConcurrentHashMap.newKeySet();
    private final Consumer<String> log;
    private volatile boolean closed;

    EventStreams(Consumer<String> log) {
        this.log = log;
    }

    /**
     * Adds a client; {@code first} is its first event, then every event published from now on.
     *
     * @throws ServiceError 503 when {@value #MAX_CLIENTS} clients are connected
     */
    Subscriber open(String name, Sink sink, LiveEvent first) {
        if (closed) {
            throw new ServiceError(503, "stopping", "the service is stopping");
        }
        Subscriber s = new Subscriber(name, sink);
        s.queue.add(first);
        synchronized (subscribers) {
            if (subscribers.size() >= MAX_CLIENTS) {
                throw new ServiceError(503, "too-many-streams", "already " + MAX_CLIENTS + " event-stream clients (the limit); try again later");
            }
            subscribers.add(s);
        }
        s.thread.start();
        return s;
    }

    /** Queues the event for every client; never blocks. */
    void publish(LiveEvent e) {
        for (Subscriber s : subscribers) {
            s.offer(e);
        }
    }

    int clients() {
        return subscribers.size();
    }

    void close() {
        closed = true;
        subscribers.forEach(s -> s.drop(null));
    }

    final class Subscriber {
        private final String name;
        private final Sink sink;
        private final BlockingQueue<LiveEvent> queue = new ArrayBlockingQueue<>(QUEUE);
        private final Thread thread;
        private volatile boolean dropped;

        private Subscriber(String name, Sink sink) {
            this.name = name;
            this.sink = sink;
            this.thread = new Thread(this::run, "triad-events-" + name);
            this.thread.setDaemon(true);
        }

        private void offer(LiveEvent e) {
            if (!dropped && !queue.offer(e)) {
                drop("fell " + QUEUE + " events behind (not reading)");
            }
        }

        /** Stops sending to this client and ends its connection; {@code why} is logged unless null. */
        void drop(String why) {
            if (dropped) {
                return;
            }
            dropped = true;
            subscribers.remove(this);
            if (why != null) {
                log.accept("triad serve: dropped event-stream client " + name + ": " + why);
            }
            thread.interrupt();
            try {
                sink.close();
            } catch (RuntimeException e) {
                // already gone
            }
        }

        private void run() {
            try {
                while (!dropped) {
                    LiveEvent e = queue.take();
                    sink.send(e.type(), e.data());
                }
            } catch (InterruptedException e) {
                // dropped
            } catch (Exception e) {
                drop(null); // the client went away
            }
        }
    }
}
