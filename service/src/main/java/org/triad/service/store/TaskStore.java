package org.triad.service.store;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.sql.Timestamp;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.flywaydb.core.api.FlywayException;
import org.triad.service.ServiceError;
import org.triad.service.store.Records.EventRow;
import org.triad.service.store.Records.RequestRow;
import org.triad.service.store.Records.TaskRow;

/**
 * The service's database: the embedded default (SQLite, see {@link Database}) or PostgreSQL, its
 * schema kept by Flyway migrations ({@code db/migration}, portable SQL). One connection, one writer
 * at a time: every change is committed (and on the embedded file synced to disk) before the method
 * returns, so an accepted task survives a crash. A failed call drops the connection, and the next
 * call opens a new one: the store heals by itself once a full disk has room again or the server is
 * back; {@link #health()} tells what happened.
 */
public final class TaskStore implements AutoCloseable {
    private final Database db;
    private final StoreHealth health;
    private final String notice;
    private Connection connection;

    private TaskStore(Database db, Connection connection, String notice) {
        this.db = db;
        this.connection = connection;
        this.notice = notice;
        this.health = new StoreHealth(db.shown());
    }

    /** Opens the embedded database {@code file} (see {@link EmbeddedFile#of}). */
    public static TaskStore open(Path file) {
        return open(Database.embedded(file));
    }

    /**
     * Opens (creating and migrating as needed) the database.
     *
     * @throws ServiceError a start-up error when the file is locked by another process, read-only,
     *                      damaged (with the recovery command), or the server cannot be reached
     */
    public static TaskStore open(Database db) {
        EmbeddedFile f = db.file();
        String notice = null;
        if (f != null) {
            f.prepare();
        }
        try {
            if (f != null) {
                if (!Files.exists(f.file()) && Files.exists(f.legacyH2())) {
                    notice = Migrations.fromH2(f, db);
                }
                f.check(db);
            }
            try {
                Migrations.migrate(db);
                return new TaskStore(db, db.connect(), notice);
            } catch (FlywayException | SQLException e) {
                throw ServiceError.startup("database " + db.shown() + ": " + describe(e));
            }
        } catch (RuntimeException e) {
            if (f != null) {
                f.release();
            }
            throw e;
        }
    }

    private static String describe(Throwable e) {
        return Migrations.firstLine(e);
    }

    /** What the start did besides opening, e.g. moving an H2 file of an earlier version; null if nothing. */
    public String notice() {
        return notice;
    }

    public Database database() {
        return db;
    }

    public StoreHealth health() {
        return health;
    }

    /** One call on the connection, opening a new one first if the last call failed. */
    private interface Work<T> {
        T run(Connection c) throws SQLException;
    }

    private synchronized <T> T work(Work<T> w) {
        try {
            if (connection == null) {
                connection = db.connect();
            }
            T result = w.run(connection);
            health.succeeded();
            return result;
        } catch (SQLException e) {
            health.failed(describe(e));
            // a full disk or a lost server may have left the connection unusable: the next call opens a new one
            try {
                if (connection != null) {
                    connection.close();
                }
            } catch (SQLException ignored) {
                // it is being replaced
            }
            connection = null;
            throw unavailable(e);
        }
    }

    /** The embedded file, or null on a server. */
    public Path file() {
        return db.file() == null ? null : db.file().file();
    }

    // ---- tasks --------------------------------------------------------------------------------

    public TaskRow insertTask(String task, String argsJson, Instant now) {
        return insertTask(task, argsJson, 0, now);
    }

    public TaskRow insertTask(String task, String argsJson, int priority, Instant now) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement(
                    "INSERT INTO task(name, args, state, submitted_at, updated_at, priority) VALUES (?, ?, ?, ?, ?, ?)", Statement.RETURN_GENERATED_KEYS)) {
                s.setString(1, task);
                s.setString(2, argsJson);
                s.setString(3, TaskState.QUEUED.name());
                s.setTimestamp(4, Timestamp.from(now));
                s.setTimestamp(5, Timestamp.from(now));
                s.setInt(6, priority);
                s.executeUpdate();
                return new TaskRow(generatedKey(s), task, argsJson, TaskState.QUEUED, null, null, null, now, now, priority);
            }
        });
    }

    /** A stored submission: the task's row and its first event; {@code created} false when the key named a task stored before (event null). */
    public record Submitted(TaskRow task, EventRow event, boolean created) {
    }

    /** Stores a submitted task with its first event ({@code submitted}) in one transaction: both or neither. */
    public TaskRow insertTask(String task, String argsJson, Instant now, String submittedText) {
        return submitTask(task, argsJson, now, submittedText).task();
    }

    /** As {@link #insertTask(String, String, Instant, String)}, with the event (priority 0). */
    public Submitted submitTask(String task, String argsJson, Instant now, String submittedText) {
        return submitTask(task, argsJson, 0, now, submittedText, null);
    }

    /**
     * Stores a submission under the client's idempotency {@code key} (null: none); a key stored before
     * returns that task instead ({@code created} false), whatever its state.
     */
    public Submitted submitTask(String task, String argsJson, int priority, Instant now, String submittedText, String key) {
        if (key != null) {
            List<TaskRow> before = tasks("SELECT * FROM task WHERE submission_key = ?", key);
            if (!before.isEmpty()) {
                return new Submitted(before.get(0), null, false);
            }
        }
        return transaction(c -> {
            long id;
            try (PreparedStatement s = c.prepareStatement(
                    "INSERT INTO task(name, args, state, submitted_at, updated_at, submission_key, priority) VALUES (?, ?, ?, ?, ?, ?, ?)",
                    Statement.RETURN_GENERATED_KEYS)) {
                bind(s, task, argsJson, TaskState.QUEUED.name(), Timestamp.from(now), Timestamp.from(now), key, priority);
                s.executeUpdate();
                id = generatedKey(s);
            }
            EventRow event = insertEvent(c, id, "submitted", null, submittedText, now);
            return new Submitted(new TaskRow(id, task, argsJson, TaskState.QUEUED, null, null, null, now, now, priority), event, true);
        });
    }

    /** Records a dispatch (event and state {@code running} on {@code robot}) in one transaction. */
    public void dispatchTask(long id, String robot, String text, Instant now) {
        transaction(c -> {
            insertEvent(c, id, "dispatched", robot, text, now);
            try (PreparedStatement s = c.prepareStatement("UPDATE task SET state = ?, robot = ?, preferred_robot = NULL, reason = NULL, updated_at = ? WHERE id = ?")) {
                bind(s, TaskState.RUNNING.name(), robot, Timestamp.from(now), id);
                s.executeUpdate();
            }
            return null;
        });
    }

    /**
     * A robot's last report on a task, in one transaction: its events, then the task's new state if it
     * is still {@code running} on {@code robot}, and for {@code aborted} the remote-operation request.
     * A crash before the commit leaves the task running (queued again at the next start, its events
     * not written); after it, the task is finished: never both, so a task does not complete twice.
     *
     * @param events {@code [kind, text]} pairs
     * @param request the remote-operation request's {@code [goal, reason]} when the task becomes aborted, else null
     */
    public boolean finishTask(long id, String robot, List<String[]> events, TaskState state, String newRobot, String reason, String[] request,
            Instant now) {
        return transaction(c -> {
            for (String[] e : events) {
                insertEvent(c, id, e[0], robot, e[1], now);
            }
            int changed;
            try (PreparedStatement s = c.prepareStatement(
                    "UPDATE task SET state = ?, robot = ?, preferred_robot = NULL, reason = ?, updated_at = ? WHERE id = ? AND state = ? AND robot = ?")) {
                bind(s, state.name(), newRobot, reason, Timestamp.from(now), id, TaskState.RUNNING.name(), robot);
                changed = s.executeUpdate();
            }
            if (request != null && changed == 1) {
                try (PreparedStatement s = c.prepareStatement("INSERT INTO remote_request(task_id, robot, goal, reason, raised_at) VALUES (?, ?, ?, ?, ?)")) {
                    bind(s, id, robot, request[0], request[1].length() > 4000 ? request[1].substring(0, 3997) + "..." : request[1], Timestamp.from(now));
                    s.executeUpdate();
                }
            }
            return changed == 1;
        });
    }

    public void updateTask(long id, TaskState state, String robot, String preferredRobot, String reason, Instant now) {
        update("UPDATE task SET state = ?, robot = ?, preferred_robot = ?, reason = ?, updated_at = ? WHERE id = ?", state.name(), robot, preferredRobot,
                reason, Timestamp.from(now), id);
    }

    /**
     * Sets the task's state only if it is still {@code expected} on {@code robot}; false when another
     * instance or a re-plan has changed it meanwhile (a robot's late report must not undo that).
     */
    public boolean updateTaskIf(long id, TaskState expected, String expectedRobot, TaskState state, String robot, String reason, Instant now) {
        return update("UPDATE task SET state = ?, robot = ?, preferred_robot = NULL, reason = ?, updated_at = ? WHERE id = ? AND state = ? AND robot = ?",
                state.name(), robot, reason, Timestamp.from(now), id, expected.name(), expectedRobot) == 1;
    }

    public Optional<TaskRow> task(long id) {
        List<TaskRow> rows = tasks("SELECT * FROM task WHERE id = ?", id);
        return rows.isEmpty() ? Optional.empty() : Optional.of(rows.get(0));
    }

    /** Tasks in {@code state} (all when null), newest first, at most {@code limit}. */
    public List<TaskRow> tasks(TaskState state, int limit) {
        return state == null ? tasks("SELECT * FROM task ORDER BY id DESC LIMIT ?", limit)
                : tasks("SELECT * FROM task WHERE state = ? ORDER BY id DESC LIMIT ?", state.name(), limit);
    }

    /** Tasks in {@code state}, oldest first: the queue order. */
    public List<TaskRow> tasksInOrder(TaskState state) {
        return tasks("SELECT * FROM task WHERE state = ? ORDER BY id", state.name());
    }

    private List<TaskRow> tasks(String sql, Object... params) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement(sql)) {
                bind(s, params);
                List<TaskRow> out = new ArrayList<>();
                try (ResultSet r = s.executeQuery()) {
                    while (r.next()) {
                        out.add(new TaskRow(r.getLong("id"), r.getString("name"), r.getString("args"), TaskState.valueOf(r.getString("state")),
                                r.getString("robot"), r.getString("preferred_robot"), r.getString("reason"), instant(r, "submitted_at"),
                                instant(r, "updated_at"), r.getInt("priority")));
                    }
                }
                return out;
            }
        });
    }

    // ---- Status history -----------------------------------------------------------------------

    public EventRow insertEvent(long taskId, String kind, String robot, String text, Instant now) {
        return work(c -> insertEvent(c, taskId, kind, robot, text, now));
    }

    private static EventRow insertEvent(Connection c, long taskId, String kind, String robot, String text, Instant now) throws SQLException {
        String clipped = text.length() > 4000 ? text.substring(0, 3997) + "..." : text;
        try (PreparedStatement s = c.prepareStatement("INSERT INTO task_event(task_id, at, kind, robot, text) VALUES (?, ?, ?, ?, ?)",
                Statement.RETURN_GENERATED_KEYS)) {
            bind(s, taskId, Timestamp.from(now), kind, robot, clipped);
            s.executeUpdate();
            return new EventRow(generatedKey(s), taskId, now, kind, robot, clipped);
        }
    }

    public List<EventRow> events(long taskId) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement("SELECT * FROM task_event WHERE task_id = ? ORDER BY id")) {
                s.setLong(1, taskId);
                List<EventRow> out = new ArrayList<>();
                try (ResultSet r = s.executeQuery()) {
                    while (r.next()) {
                        out.add(new EventRow(r.getLong("id"), taskId, instant(r, "at"), r.getString("kind"), r.getString("robot"), r.getString("text")));
                    }
                }
                return out;
            }
        });
    }

    // ---- remote-operation requests ------------------------------------------------------------

    public RequestRow insertRequest(long taskId, String robot, String goal, String reason, Instant now) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement("INSERT INTO remote_request(task_id, robot, goal, reason, raised_at) VALUES (?, ?, ?, ?, ?)",
                    Statement.RETURN_GENERATED_KEYS)) {
                bind(s, taskId, robot, goal, reason.length() > 4000 ? reason.substring(0, 3997) + "..." : reason, Timestamp.from(now));
                s.executeUpdate();
                return new RequestRow(generatedKey(s), taskId, robot, goal, reason, now, null, null);
            }
        });
    }

    /** Resolves the task's open requests; returns how many there were. */
    public int resolveRequests(long taskId, String resolution, Instant now) {
        return update("UPDATE remote_request SET resolved_at = ?, resolution = ? WHERE task_id = ? AND resolved_at IS NULL", Timestamp.from(now),
                resolution, taskId);
    }

    public List<RequestRow> requests(boolean includeResolved) {
        String sql = includeResolved ? "SELECT * FROM remote_request ORDER BY id DESC LIMIT 500"
                : "SELECT * FROM remote_request WHERE resolved_at IS NULL ORDER BY id";
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement(sql)) {
                List<RequestRow> out = new ArrayList<>();
                try (ResultSet r = s.executeQuery()) {
                    while (r.next()) {
                        out.add(new RequestRow(r.getLong("id"), r.getLong("task_id"), r.getString("robot"), r.getString("goal"), r.getString("reason"),
                                instant(r, "raised_at"), instant(r, "resolved_at"), r.getString("resolution")));
                    }
                }
                return out;
            }
        });
    }

    // ---- settings -----------------------------------------------------------------------------

    public Optional<String> setting(String name) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement("SELECT val FROM setting WHERE name = ?")) {
                s.setString(1, name);
                try (ResultSet r = s.executeQuery()) {
                    return r.next() ? Optional.of(r.getString(1)) : Optional.empty();
                }
            }
        });
    }

    public void putSetting(String name, String value) {
        // INSERT ... ON CONFLICT: the same upsert in SQLite and PostgreSQL
        update("INSERT INTO setting(name, val) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET val = excluded.val", name, value);
    }

    // ---- for the users and audit store (org.triad.service.auth) ---------------------------------

    /** SQL run on the store's one connection. */
    @FunctionalInterface
    public interface SqlWork<T> {
        T apply(Connection connection) throws SQLException;
    }

    /** Runs {@code sql} on the store's connection, one writer at a time; a failure is a 503 like the store's own. */
    public <T> T withConnection(SqlWork<T> sql) {
        // through work(): a failed call reopens the connection like the store's own calls, so the users and audit heal too
        return work(sql::apply);
    }

    @Override
    public synchronized void close() {
        try {
            if (connection != null) {
                connection.close();
            }
        } catch (SQLException e) {
            // closing at shutdown: nothing left to save
        }
        connection = null;
        if (db.file() != null) {
            db.file().release();
        }
    }

    /** Several statements committed together, or none of them. */
    private <T> T transaction(Work<T> w) {
        return work(c -> {
            c.setAutoCommit(false);
            try {
                T result = w.run(c);
                c.commit();
                return result;
            } catch (SQLException | RuntimeException e) {
                try {
                    c.rollback();
                } catch (SQLException ignored) {
                    // the connection is dropped after the failure anyway
                }
                throw e;
            } finally {
                try {
                    c.setAutoCommit(true);
                } catch (SQLException ignored) {
                    // as above
                }
            }
        });
    }

    private int update(String sql, Object... params) {
        return work(c -> {
            try (PreparedStatement s = c.prepareStatement(sql)) {
                bind(s, params);
                return s.executeUpdate();
            }
        });
    }

    private static long generatedKey(PreparedStatement s) throws SQLException {
        try (ResultSet k = s.getGeneratedKeys()) {
            if (!k.next()) {
                throw new SQLException("the database returned no key for the new row");
            }
            return k.getLong(1);
        }
    }

    private static void bind(PreparedStatement s, Object... params) throws SQLException {
        for (int i = 0; i < params.length; i++) {
            Object p = params[i];
            if (p instanceof Long l) {
                s.setLong(i + 1, l);
            } else if (p instanceof Integer n) {
                s.setInt(i + 1, n);
            } else if (p instanceof Timestamp t) {
                s.setTimestamp(i + 1, t);
            } else {
                s.setString(i + 1, (String) p);
            }
        }
    }

    private static Instant instant(ResultSet r, String column) throws SQLException {
        Timestamp t = r.getTimestamp(column);
        return t == null ? null : t.toInstant();
    }

    private ServiceError unavailable(SQLException e) {
        return new ServiceError(503, "database-unavailable", "the task database " + db.shown() + " failed: " + describe(e));
    }
}
