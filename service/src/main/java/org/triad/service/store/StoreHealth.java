package org.triad.service.store;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * Whether the database works now, and the outages it had (a full disk, a lost connection): when each
 * began, what failed, when it healed. The operator page shows it; stderr gets one line per change.
 */
public final class StoreHealth {
    /** One outage; {@code healedAt} is null while it lasts. */
    public record Outage(Instant since, Instant healedAt, String cause, long failures) {
        public String describe() {
            return healedAt == null ? "the database fails since " + since + ": " + cause + " (" + failures + " failed call(s); retrying)"
                    : "the database failed from " + since + " for " + Duration.between(since, healedAt).toMillis() / 1000.0 + " s: " + cause
                            + " (" + failures + " failed call(s)); it works again";
        }
    }

    private static final int KEPT = 20;
    private final String database;
    private final Deque<Outage> outages = new ArrayDeque<>();
    private Outage current;

    StoreHealth(String database) {
        this.database = database;
    }

    synchronized void failed(String cause) {
        if (current == null) {
            current = new Outage(Instant.now(), null, cause, 1);
            System.err.println("triad serve: the database " + database + " fails: " + cause + "; retrying until it works again");
        } else {
            current = new Outage(current.since(), null, current.cause(), current.failures() + 1);
        }
    }

    synchronized void succeeded() {
        if (current != null) {
            Outage healed = new Outage(current.since(), Instant.now(), current.cause(), current.failures());
            current = null;
            outages.addFirst(healed);
            while (outages.size() > KEPT) {
                outages.removeLast();
            }
            System.err.println("triad serve: " + healed.describe());
        }
    }

    public synchronized boolean ok() {
        return current == null;
    }

    /** The outage going on now (if any) first, then the healed ones, newest first. */
    public synchronized List<Outage> outages() {
        List<Outage> out = new ArrayList<>();
        if (current != null) {
            out.add(current);
        }
        out.addAll(outages);
        return out;
    }
}
