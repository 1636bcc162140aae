package org.triad.service.store;

import java.sql.Connection;
import java.sql.DatabaseMetaData;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Timestamp;
import java.time.OffsetDateTime;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Copies the rows of the service's tables from one database into a freshly migrated one, column by
 * column where both have it (ids kept), for the H2 migration and for salvaging a damaged file. Tables
 * come from the target's schema, so tables that other migrations add are copied too.
 */
final class TableCopy {
    /** Rows copied and rows that could not be read, per table. */
    record Result(Map<String, int[]> tables) {
        String summary() {
            List<String> parts = new ArrayList<>();
            tables.forEach((t, n) -> parts.add(t + " " + n[0] + (n[1] > 0 ? " (" + n[1] + " unreadable)" : "")));
            return String.join(", ", parts);
        }

        int unreadable() {
            return tables.values().stream().mapToInt(n -> n[1]).sum();
        }
    }

    /** Reads the rows of one table from the source, in key order; may skip what it cannot read. */
    interface RowSource {
        /** The table's columns in the source, any case. */
        List<String> columns(String table) throws SQLException;

        /** Returns how many rows it had to skip because they could not be read. */
        int forEachRow(String table, List<String> columns, RowSink sink) throws SQLException;
    }

    interface RowSink {
        void accept(Object[] row) throws SQLException;
    }

    private TableCopy() {
    }

    static Result copy(Connection target, Map<String, String> sourceTables, RowSource source) throws SQLException {
        Map<String, int[]> counts = new LinkedHashMap<>();
        boolean auto = target.getAutoCommit();
        // a salvage may keep events of a task row that was unreadable: copy what there is, references or not
        try (var s = target.createStatement()) {
            s.execute("PRAGMA foreign_keys=OFF");
        }
        target.setAutoCommit(false);
        try {
            for (String table : tables(target)) {
                String sourceTable = sourceTables.get(table.toLowerCase(Locale.ROOT));
                if (sourceTable == null) {
                    continue;
                }
                List<String> there = source.columns(sourceTable).stream().map(x -> x.toLowerCase(Locale.ROOT)).toList();
                List<String> columns = columns(target, table).stream().filter(x -> there.contains(x.toLowerCase(Locale.ROOT))).toList();
                int[] n = new int[2];
                String sql = "INSERT INTO " + table + "(" + String.join(", ", columns) + ") VALUES (" + "?, ".repeat(columns.size() - 1) + "?)";
                try (PreparedStatement insert = target.prepareStatement(sql)) {
                    n[1] = source.forEachRow(sourceTable, columns, row -> {
                        for (int i = 0; i < row.length; i++) {
                            Object v = row[i];
                            if (v instanceof OffsetDateTime o) {
                                insert.setTimestamp(i + 1, Timestamp.from(o.toInstant()));
                            } else if (v instanceof Timestamp t) {
                                insert.setTimestamp(i + 1, t);
                            } else {
                                insert.setObject(i + 1, v);
                            }
                        }
                        try {
                            insert.executeUpdate();
                        } catch (SQLException e) {
                            // the new database refused a row: not a read error of the source, so it must not be skipped
                            throw new IllegalStateException("cannot write a row of " + table + ": " + e.getMessage(), e);
                        }
                        n[0]++;
                    });
                }
                counts.put(table, n);
            }
            target.commit();
        } catch (SQLException | RuntimeException e) {
            target.rollback();
            throw e;
        } finally {
            target.setAutoCommit(auto);
        }
        return new Result(counts);
    }

    /** The target's tables in creation order (so referenced rows come first), without Flyway's history. */
    static List<String> tables(Connection c) throws SQLException {
        List<String> out = new ArrayList<>();
        try (ResultSet r = c.createStatement().executeQuery("SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY rowid")) {
            while (r.next()) {
                String t = r.getString(1);
                if (!t.equalsIgnoreCase("flyway_schema_history") && !t.startsWith("sqlite_")) {
                    out.add(t);
                }
            }
        }
        return out;
    }

    static List<String> columns(Connection c, String table) throws SQLException {
        List<String> out = new ArrayList<>();
        DatabaseMetaData md = c.getMetaData();
        try (ResultSet r = md.getColumns(null, null, table, null)) {
            while (r.next()) {
                out.add(r.getString("COLUMN_NAME"));
            }
        }
        return out;
    }
}
