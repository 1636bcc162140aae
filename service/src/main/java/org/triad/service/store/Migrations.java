package org.triad.service.store;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.flywaydb.core.Flyway;
import org.sqlite.SQLiteConfig;
import org.triad.service.ServiceError;

/**
 * Schema and file migrations of the embedded database: Flyway's migrations ({@code db/migration},
 * portable SQL), the one-time move of an H2 file of earlier versions into SQLite, and the salvage of
 * a damaged file into a new one ({@code --recover}).
 */
public final class Migrations {
    private Migrations() {
    }

    static void migrate(Database db) {
        Flyway.configure().dataSource(db.url(), db.properties().getProperty("user"), db.properties().getProperty("password"))
                .locations("classpath:db/migration").placeholders(db.dialect().placeholders()).load().migrate();
    }

    /**
     * Moves the rows of {@code NAME.mv.db} (H2, earlier versions) into a new {@code NAME.db}; the H2
     * file is kept as {@code NAME.mv.db.migrated}. Returns what was moved, for the start-up message.
     */
    static String fromH2(EmbeddedFile f, Database db) {
        Path h2 = f.legacyH2();
        String base = h2.toString().substring(0, h2.toString().length() - ".mv.db".length());
        Path partial = sibling(f.file(), ".migrating.db");
        try {
            Files.deleteIfExists(partial);
            Database target = Database.embedded(partial);
            migrate(target);
            TableCopy.Result result;
            try (Connection from = DriverManager.getConnection("jdbc:h2:file:" + base + ";IFEXISTS=TRUE", "triad", "");
                    Connection to = target.connect()) {
                Map<String, String> tables = new LinkedHashMap<>();
                try (ResultSet r = from.createStatement().executeQuery(
                        "SELECT TABLE_NAME FROM INFORMATION_SCHEMA.TABLES WHERE TABLE_SCHEMA = 'PUBLIC' AND TABLE_TYPE = 'BASE TABLE'")) {
                    while (r.next()) {
                        tables.put(r.getString(1).toLowerCase(Locale.ROOT), r.getString(1));
                    }
                }
                result = TableCopy.copy(to, tables, new TableCopy.RowSource() {
                    @Override
                    public List<String> columns(String table) throws SQLException {
                        List<String> out = new ArrayList<>();
                        try (ResultSet r = from.getMetaData().getColumns(null, "PUBLIC", table, null)) {
                            while (r.next()) {
                                out.add(r.getString("COLUMN_NAME"));
                            }
                        }
                        return out;
                    }

                    @Override
                    public int forEachRow(String table, List<String> columns, TableCopy.RowSink sink) throws SQLException {
                        try (Statement s = from.createStatement(); ResultSet r = s.executeQuery("SELECT " + String.join(", ", columns) + " FROM " + table
                                + (columns.stream().anyMatch(c -> c.equalsIgnoreCase("id")) ? " ORDER BY id" : ""))) {
                            while (r.next()) {
                                Object[] row = new Object[columns.size()];
                                for (int i = 0; i < row.length; i++) {
                                    row[i] = r.getObject(i + 1);
                                }
                                sink.accept(row);
                            }
                        }
                        return 0;
                    }
                });
            }
            Files.move(partial, f.file(), StandardCopyOption.ATOMIC_MOVE);
            Files.move(h2, h2.resolveSibling(h2.getFileName() + ".migrated"), StandardCopyOption.ATOMIC_MOVE);
            return "moved the H2 database " + h2 + " into " + f.file() + " (" + result.summary() + "); the H2 file is kept as "
                    + h2.getFileName() + ".migrated";
        } catch (SQLException | IOException | RuntimeException e) {
            try {
                Files.deleteIfExists(partial);
            } catch (IOException ignored) {
                // the half-made copy is re-made at the next start
            }
            if (e instanceof ServiceError s) {
                throw s;
            }
            throw ServiceError.startup("database " + h2 + " (H2, from an earlier version) cannot be moved to " + f.file() + ": " + firstLine(e)
                    + ". Nothing was changed. If the H2 file is damaged, salvage it with H2's own tool: java -cp h2-2.2.224.jar org.h2.tools.Recover -dir "
                    + h2.getParent() + " -db " + Path.of(base).getFileName());
        }
    }

    /**
     * Copies every readable row of a damaged database into a new file, which takes its place; the
     * damaged one is kept as {@code NAME.db.damaged-TIME}. Returns what was saved, for the user.
     */
    public static String salvage(Path path) {
        EmbeddedFile f = EmbeddedFile.of(path);
        if (!Files.exists(f.file())) {
            throw ServiceError.startup("--recover: there is no database " + f.file());
        }
        f.prepare();
        Path fresh = sibling(f.file(), ".recovering.db");
        try {
            Files.deleteIfExists(fresh);
            Database target = Database.embedded(fresh);
            migrate(target);
            SQLiteConfig readOnly = new SQLiteConfig();
            readOnly.setReadOnly(true);
            TableCopy.Result result;
            try (Connection from = readOnly.createConnection("jdbc:sqlite:" + f.file()); Connection to = target.connect()) {
                Map<String, String> tables = new LinkedHashMap<>();
                try (ResultSet r = from.createStatement().executeQuery("SELECT name FROM sqlite_master WHERE type = 'table'")) {
                    while (r.next()) {
                        tables.put(r.getString(1).toLowerCase(Locale.ROOT), r.getString(1));
                    }
                } catch (SQLException e) {
                    throw ServiceError.startup("--recover: the list of tables of " + f.file() + " is unreadable (" + firstLine(e)
                            + "); try SQLite's own salvage: sqlite3 " + f.file() + " .recover | sqlite3 " + fresh.getFileName());
                }
                result = TableCopy.copy(to, tables, new SalvagingSource(from));
            }
            String stamp = LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss"));
            Path kept = f.file().resolveSibling(f.file().getFileName() + ".damaged-" + stamp);
            Files.move(f.file(), kept, StandardCopyOption.ATOMIC_MOVE);
            for (String suffix : new String[] { "-wal", "-shm" }) {
                Path side = f.file().resolveSibling(f.file().getFileName() + suffix);
                if (Files.exists(side)) {
                    Files.move(side, kept.resolveSibling(kept.getFileName() + suffix), StandardCopyOption.ATOMIC_MOVE);
                }
            }
            Files.move(fresh, f.file(), StandardCopyOption.ATOMIC_MOVE);
            return "recovered " + f.file() + ": " + result.summary() + (result.unreadable() > 0 ? "; unreadable rows are lost" : "")
                    + "; the damaged file is kept as " + kept.getFileName();
        } catch (SQLException | IOException | IllegalStateException e) {
            throw ServiceError.startup("--recover " + f.file() + " failed: " + firstLine(e));
        } finally {
            f.release();
            try {
                Files.deleteIfExists(fresh);
            } catch (IOException ignored) {
                // nothing to keep of a failed salvage
            }
        }
    }

    /** Reads a table in rowid order; past a row it cannot read it probes the following rowids one by one. */
    private record SalvagingSource(Connection from) implements TableCopy.RowSource {
        private static final int GIVE_UP_AFTER = 100_000;

        @Override
        public List<String> columns(String table) throws SQLException {
            List<String> out = new ArrayList<>();
            try (ResultSet r = from.createStatement().executeQuery("PRAGMA table_info(" + table + ")")) {
                while (r.next()) {
                    out.add(r.getString("name"));
                }
            }
            return out;
        }

        @Override
        public int forEachRow(String table, List<String> columns, TableCopy.RowSink sink) throws SQLException {
            String select = "SELECT rowid, " + String.join(", ", columns) + " FROM " + table;
            long next = Long.MIN_VALUE;
            int skipped = 0;
            while (true) {
                long last = scan(select + " WHERE rowid >= ? ORDER BY rowid", next, columns.size(), sink);
                if (last == Long.MAX_VALUE) {
                    return skipped;
                }
                // the scan broke after rowid 'last': probe the rowids after it
                long probe = last + 1;
                int misses = 0;
                boolean found = false;
                while (misses < GIVE_UP_AFTER && !found) {
                    try (PreparedStatement s = from.prepareStatement(select + " WHERE rowid = ?")) {
                        s.setLong(1, probe);
                        try (ResultSet r = s.executeQuery()) {
                            found = r.next();
                        }
                    } catch (SQLException e) {
                        found = false;
                    }
                    if (!found) {
                        probe++;
                        misses++;
                    }
                }
                if (!found) {
                    // rowids run on without gaps (rows are never deleted): at least the row after the last read one is lost
                    return skipped + 1;
                }
                // the service never deletes rows, so every rowid between two readable ones was a row
                skipped += (int) (probe - last - 1);
                next = probe;
            }
        }

        /** Streams rows from rowid {@code from}; returns Long.MAX_VALUE at the end, else the last rowid read before a failure. */
        private long scan(String sql, long fromRowid, int n, TableCopy.RowSink sink) throws SQLException {
            long last = fromRowid == Long.MIN_VALUE ? 0 : fromRowid - 1;
            try (PreparedStatement s = from.prepareStatement(sql)) {
                s.setLong(1, fromRowid);
                try (ResultSet r = s.executeQuery()) {
                    while (r.next()) {
                        Object[] row = new Object[n];
                        for (int i = 0; i < n; i++) {
                            row[i] = r.getObject(i + 2);
                        }
                        long rowid = r.getLong(1);
                        sink.accept(row);
                        last = rowid;
                    }
                }
                return Long.MAX_VALUE;
            } catch (SQLException e) {
                return last;
            }
        }
    }

    /** {@code NAME.db} -> {@code NAME<ending>}, a name that {@link EmbeddedFile#of} keeps as it is. */
    private static Path sibling(Path file, String ending) {
        String name = file.getFileName().toString();
        return file.resolveSibling(name.substring(0, name.length() - ".db".length()) + ending);
    }

    static String firstLine(Throwable e) {
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        String m = root.getMessage() == null ? root.getClass().getSimpleName() : root.getMessage();
        return m.lines().findFirst().orElse(m);
    }
}
