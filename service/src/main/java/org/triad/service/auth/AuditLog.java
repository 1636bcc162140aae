package org.triad.service.auth;

import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.Timestamp;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;

import org.triad.service.store.TaskStore;

/**
 * Who did what when (table {@code audit_entry}): every operator and admin action, every cancellation and
 * every failed login. Entries are numbered by the service (one writer: the store's connection).
 */
public final class AuditLog {
    /** An entry as shown on the operator page; {@code at} is ISO-8601 UTC. */
    public record Entry(long id, String at, String who, String what, String detail) {
    }

    private static final int MAX_DETAIL = 1000;

    private final TaskStore store;

    public AuditLog(TaskStore store) {
        this.store = store;
    }

    public void record(String who, String what, String detail, Instant now) {
        String d = detail.length() > MAX_DETAIL ? detail.substring(0, MAX_DETAIL - 3) + "..." : detail;
        String w = who.length() > 100 ? who.substring(0, 97) + "..." : who;
        store.withConnection(c -> {
            long id;
            try (PreparedStatement s = c.prepareStatement("SELECT COALESCE(MAX(id), 0) + 1 FROM audit_entry"); ResultSet r = s.executeQuery()) {
                r.next();
                id = r.getLong(1);
            }
            try (PreparedStatement s = c.prepareStatement("INSERT INTO audit_entry(id, happened_at, who, what, detail) VALUES (?, ?, ?, ?, ?)")) {
                s.setLong(1, id);
                s.setTimestamp(2, Timestamp.from(now));
                s.setString(3, w);
                s.setString(4, what);
                s.setString(5, d);
                s.executeUpdate();
            }
            return null;
        });
    }

    /** The newest entries, newest first. */
    public List<Entry> recent(int limit) {
        return store.withConnection(c -> {
            List<Entry> entries = new ArrayList<>();
            try (PreparedStatement s = c.prepareStatement("SELECT id, happened_at, who, what, detail FROM audit_entry ORDER BY id DESC")) {
                s.setMaxRows(limit);
                try (ResultSet r = s.executeQuery()) {
                    while (r.next()) {
                        entries.add(new Entry(r.getLong(1), r.getTimestamp(2).toInstant().toString(), r.getString(3), r.getString(4), r.getString(5)));
                    }
                }
            }
            return entries;
        });
    }
}
