package org.triad.service.store;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.sql.Timestamp;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.flywaydb.core.Flyway;
import org.flywaydb.core.api.FlywayException;
import org.h2.jdbcx.JdbcDataSource;
import org.triad.service.ServiceError;
import org.triad.service.store.Records.EventRow;
import org.triad.service.store.Records.RequestRow;
import org.triad.service.store.Records.TaskRow;

/**
 * The service's embedded H2 database (one file), its schema kept by Flyway migrations
 * ({@code db/migration}). One connection, one writer at a time: every change is committed before the
 * method returns, so an accepted task survives a crash.
 */
public final class TaskStore implements AutoCloseable {
    private final Path file;
    private final Connection connection;

    private TaskStore(Path file, Connection connection) {
        this.file = file;
        this.connection = connection;
    }

    /**
     * Opens (creating and migrating as needed) the database {@code file} ({@code NAME.mv.db}, or
     * {@code NAME}, to which H2 adds {@code .mv.db}).
     *
     * @throws ServiceError a start-up error when the file is locked by another process, read-only or unreadable
     */
    public static TaskStore open(Path file) {
        Path base = file.toAbsolutePath().normalize();
        String name = base.getFileName().toString();
        if (name.endsWith(".mv.db")) {
            base = base.resolveSibling(name.substring(0, name.length() - ".mv.db".length()));
        }
        Path dbFile = base.resolveSibling(base.getFileName() + ".mv.db");
        Path folder = base.getParent();
        if (folder != null && !Files.isDirectory(folder)) {
            throw ServiceError.startup("database " + dbFile + ": the folder " + folder + " does not exist");
        }
        if (Files.exists(dbFile) && !Files.isWritable(dbFile)) {
            throw ServiceError.startup("database " + dbFile + " is read-only: the service must write every task it accepts");
        }
        if (!Files.exists(dbFile) && folder != null && !Files.isWritable(folder)) {
            throw ServiceError.startup("database " + dbFile + " cannot be created: the folder " + folder + " is read-only");
        }
        JdbcDataSource ds = new JdbcDataSource();
        ds.setURL("jdbc:h2:file:" + base + ";DB_CLOSE_ON_EXIT=FALSE");
        ds.setUser("triad");
        ds.setPassword("");
        try {
            Flyway.configure().dataSource(ds).locations("classpath:db/migration").load().migrate();
            Connection c = DriverManager.getConnection(ds.getURL(), "triad", "");
            c.setAutoCommit(true);
            return new TaskStore(dbFile, c);
        } catch (FlywayException | SQLException e) {
            throw ServiceError.startup("database " + dbFile + ": " + describe(e));
        }
    }

    private static String describe(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof SQLException s && s.getErrorCode() == org.h2.api.ErrorCode.DATABASE_ALREADY_OPEN_1) {
                return "in use by another process (is another 'triad serve' running on it?)";
            }
            if (t instanceof SQLException s && s.getErrorCode() == org.h2.api.ErrorCode.FILE_CORRUPTED_1) {
                return "not a Triad service database or damaged";
            }
        }
        Throwable root = e;
        while (root.getCause() != null) {
            root = root.getCause();
        }
        String m = root.getMessage() == null ? root.getClass().getSimpleName() : root.getMessage();
        return m.lines().findFirst().orElse(m);
    }

    public Path file() {
        return file;
    }

    // ---- tasks --------------------------------------------------------------------------------

    public synchronized TaskRow insertTask(String task, String argsJson, Instant now) {
        return insertTask(task, argsJson, 0, now);
    }

    public synchronized TaskRow insertTask(String task, String argsJson, int priority, Instant now) {
        try (PreparedStatement s = connection.prepareStatement(
                "INSERT INTO task(name, args, state, submitted_at, updated_at, priority) VALUES (?, ?, ?, ?, ?, ?)", Statement.RETURN_GENERATED_KEYS)) {
            s.setString(1, task);
            s.setString(2, argsJson);
            s.setString(3, TaskState.QUEUED.name());
            s.setTimestamp(4, Timestamp.from(now));
            s.setTimestamp(5, Timestamp.from(now));
            s.setInt(6, priority);
            s.executeUpdate();
            try (ResultSet k = s.getGeneratedKeys()) {
                k.next();
                return new TaskRow(k.getLong(1), task, argsJson, TaskState.QUEUED, null, null, null, now, now, priority);
            }
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    public synchronized void updateTask(long id, TaskState state, String robot, String preferredRobot, String reason, Instant now) {
        try (PreparedStatement s = connection.prepareStatement(
                "UPDATE task SET state = ?, robot = ?, preferred_robot = ?, reason = ?, updated_at = ? WHERE id = ?")) {
            s.setString(1, state.name());
            s.setString(2, robot);
            s.setString(3, preferredRobot);
            s.setString(4, reason);
            s.setTimestamp(5, Timestamp.from(now));
            s.setLong(6, id);
            s.executeUpdate();
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    public synchronized Optional<TaskRow> task(long id) {
        List<TaskRow> rows = tasks("SELECT * FROM task WHERE id = ?", id);
        return rows.isEmpty() ? Optional.empty() : Optional.of(rows.get(0));
    }

    /** Tasks in {@code state} (all when null), newest first, at most {@code limit}. */
    public synchronized List<TaskRow> tasks(TaskState state, int limit) {
        return state == null ? tasks("SELECT * FROM task ORDER BY id DESC LIMIT ?", limit)
                : tasks("SELECT * FROM task WHERE state = ? ORDER BY id DESC LIMIT ?", state.name(), limit);
    }

    /** Tasks in {@code state}, oldest first: the queue order. */
    public synchronized List<TaskRow> tasksInOrder(TaskState state) {
        return tasks("SELECT * FROM task WHERE state = ? ORDER BY id", state.name());
    }

    private List<TaskRow> tasks(String sql, Object... params) {
        try (PreparedStatement s = connection.prepareStatement(sql)) {
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
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    // ---- Status history -----------------------------------------------------------------------

    public synchronized EventRow insertEvent(long taskId, String kind, String robot, String text, Instant now) {
        String clipped = text.length() > 4000 ? text.substring(0, 3997) + "..." : text;
        try (PreparedStatement s = connection.prepareStatement("INSERT INTO task_event(task_id, at, kind, robot, text) VALUES (?, ?, ?, ?, ?)",
                Statement.RETURN_GENERATED_KEYS)) {
            s.setLong(1, taskId);
            s.setTimestamp(2, Timestamp.from(now));
            s.setString(3, kind);
            s.setString(4, robot);
            s.setString(5, clipped);
            s.executeUpdate();
            try (ResultSet k = s.getGeneratedKeys()) {
                k.next();
                return new EventRow(k.getLong(1), taskId, now, kind, robot, clipped);
            }
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    public synchronized List<EventRow> events(long taskId) {
        try (PreparedStatement s = connection.prepareStatement("SELECT * FROM task_event WHERE task_id = ? ORDER BY id")) {
            s.setLong(1, taskId);
            List<EventRow> out = new ArrayList<>();
            try (ResultSet r = s.executeQuery()) {
                while (r.next()) {
                    out.add(new EventRow(r.getLong("id"), taskId, instant(r, "at"), r.getString("kind"), r.getString("robot"), r.getString("text")));
                }
            }
            return out;
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    // ---- remote-operation requests ------------------------------------------------------------

    public synchronized RequestRow insertRequest(long taskId, String robot, String goal, String reason, Instant now) {
        try (PreparedStatement s = connection.prepareStatement(
                "INSERT INTO remote_request(task_id, robot, goal, reason, raised_at) VALUES (?, ?, ?, ?, ?)", Statement.RETURN_GENERATED_KEYS)) {
            s.setLong(1, taskId);
            s.setString(2, robot);
            s.setString(3, goal);
            s.setString(4, reason.length() > 4000 ? reason.substring(0, 3997) + "..." : reason);
            s.setTimestamp(5, Timestamp.from(now));
            s.executeUpdate();
            try (ResultSet k = s.getGeneratedKeys()) {
                k.next();
                return new RequestRow(k.getLong(1), taskId, robot, goal, reason, now, null, null);
            }
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    /** Resolves the task's open requests; returns how many there were. */
    public synchronized int resolveRequests(long taskId, String resolution, Instant now) {
        try (PreparedStatement s = connection.prepareStatement(
                "UPDATE remote_request SET resolved_at = ?, resolution = ? WHERE task_id = ? AND resolved_at IS NULL")) {
            s.setTimestamp(1, Timestamp.from(now));
            s.setString(2, resolution);
            s.setLong(3, taskId);
            return s.executeUpdate();
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    public synchronized List<RequestRow> requests(boolean includeResolved) {
        String sql = includeResolved ? "SELECT * FROM remote_request ORDER BY id DESC LIMIT 500"
                : "SELECT * FROM remote_request WHERE resolved_at IS NULL ORDER BY id";
        try (PreparedStatement s = connection.prepareStatement(sql)) {
            List<RequestRow> out = new ArrayList<>();
            try (ResultSet r = s.executeQuery()) {
                while (r.next()) {
                    out.add(new RequestRow(r.getLong("id"), r.getLong("task_id"), r.getString("robot"), r.getString("goal"), r.getString("reason"),
                            instant(r, "raised_at"), instant(r, "resolved_at"), r.getString("resolution")));
                }
            }
            return out;
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    // ---- settings -----------------------------------------------------------------------------

    public synchronized Optional<String> setting(String name) {
        try (PreparedStatement s = connection.prepareStatement("SELECT val FROM setting WHERE name = ?")) {
            s.setString(1, name);
            try (ResultSet r = s.executeQuery()) {
                return r.next() ? Optional.of(r.getString(1)) : Optional.empty();
            }
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    public synchronized void putSetting(String name, String value) {
        try (PreparedStatement s = connection.prepareStatement("MERGE INTO setting(name, val) KEY(name) VALUES (?, ?)")) {
            s.setString(1, name);
            s.setString(2, value);
            s.executeUpdate();
        } catch (SQLException e) {
            throw unavailable(e);
        }
    }

    @Override
    public synchronized void close() {
        try {
            connection.close();
        } catch (SQLException e) {
            // closing at shutdown: nothing left to save
        }
    }

    private static void bind(PreparedStatement s, Object... params) throws SQLException {
        for (int i = 0; i < params.length; i++) {
            Object p = params[i];
            if (p instanceof Long l) {
                s.setLong(i + 1, l);
            } else if (p instanceof Integer n) {
                s.setInt(i + 1, n);
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
        return new ServiceError(503, "database-unavailable", "the task database " + file + " failed: " + describe(e));
    }
}
