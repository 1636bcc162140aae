package org.triad.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.service.store.Migrations;
import org.triad.service.store.Records.TaskRow;
import org.triad.service.store.TaskState;
import org.triad.service.store.TaskStore;

/** The embedded file: damage is refused with the recovery command, which saves what is readable; H2 files of earlier versions move over. */
class EmbeddedDatabaseTest {
    @TempDir
    Path dir;

    @Test
    void aDamagedPageIsRefusedWithTheRecoveryCommandWhichSavesTheReadableRows() throws Exception {
        Path db = dir.resolve("tasks");
        Instant now = Instant.parse("2026-11-24T06:00:00Z");
        try (TaskStore store = TaskStore.open(db)) {
            for (int i = 0; i < 400; i++) {
                store.insertTask("GoTo", "{\"dst\":\"room" + i + "\"}", now, "submitted: GoTo(room" + i + ")");
            }
        }
        Path file = dir.resolve("tasks.db");
        long pages = Files.size(file) / 4096;
        assertTrue(pages > 10, "pages: " + pages);
        // a page of the task table itself (where a task's arguments are stored), wherever the schema puts it
        long taskPage = pageHolding(Files.readAllBytes(file), "{\"dst\":\"room200\"}");
        assertTrue(taskPage > 0, "the task table's page: " + taskPage);
        try (RandomAccessFile f = new RandomAccessFile(file.toFile(), "rw")) {
            byte[] garbage = new byte[4096];
            Arrays.fill(garbage, (byte) 0x5a);
            f.seek(taskPage * 4096);
            f.write(garbage);
        }
        ServiceError refused = assertThrows(ServiceError.class, () -> TaskStore.open(db).close());
        String m = refused.getMessage();
        assertTrue(m.startsWith("database " + file + " is damaged: ") && m.contains("Nothing was changed") && m.contains("--db " + file + " --recover"), m);

        String said = Migrations.salvage(db);
        assertTrue(said.startsWith("recovered " + file + ": task "), said);
        try (var kept = Files.list(dir)) {
            assertEquals(1, kept.filter(p -> p.getFileName().toString().matches("tasks\\.db\\.damaged-\\d{8}-\\d{6}")).count(), said);
        }
        try (TaskStore store = TaskStore.open(db)) {
            List<TaskRow> tasks = store.tasks(null, 1000);
            assertTrue(tasks.size() > 300 && tasks.size() < 400, said + "; " + tasks.size() + " tasks");
            assertTrue(said.contains("task " + tasks.size() + " (" + (400 - tasks.size()) + " unreadable)"), said);
            for (TaskRow t : tasks) {
                assertEquals("{\"dst\":\"room" + (t.id() - 1) + "\"}", t.args(), "a recovered row is the row that was written");
            }
            long next = store.insertTask("GoTo", "{}", now, "submitted").id();
            assertTrue(next > 400, "ids are not handed out again: " + next);
        }
    }

    @Test
    void anH2DatabaseOfAnEarlierVersionMovesOverOnFirstStartKeepingIds() throws Exception {
        Path base = dir.resolve("old");
        try (Connection h2 = DriverManager.getConnection("jdbc:h2:file:" + base, "triad", ""); Statement s = h2.createStatement()) {
            s.execute("CREATE TABLE task (id BIGINT AUTO_INCREMENT PRIMARY KEY, name VARCHAR(200) NOT NULL, args VARCHAR(20000) NOT NULL,"
                    + " state VARCHAR(20) NOT NULL, robot VARCHAR(200), preferred_robot VARCHAR(200), reason VARCHAR(4000),"
                    + " submitted_at TIMESTAMP WITH TIME ZONE NOT NULL, updated_at TIMESTAMP WITH TIME ZONE NOT NULL)");
            s.execute("CREATE TABLE task_event (id BIGINT AUTO_INCREMENT PRIMARY KEY, task_id BIGINT NOT NULL REFERENCES task(id),"
                    + " at TIMESTAMP WITH TIME ZONE NOT NULL, kind VARCHAR(40) NOT NULL, robot VARCHAR(200), text VARCHAR(4000) NOT NULL)");
            s.execute("CREATE TABLE setting (name VARCHAR(100) PRIMARY KEY, val VARCHAR(1000) NOT NULL)");
            s.execute("INSERT INTO task(id, name, args, state, submitted_at, updated_at) VALUES"
                    + " (7, 'GoTo', '{\"dst\":\"xray\"}', 'QUEUED', TIMESTAMP WITH TIME ZONE '2026-11-20 10:00:00+00', TIMESTAMP WITH TIME ZONE '2026-11-20 10:00:00+00'),"
                    + " (97, 'Patrol', '{\"a\":\"storage\",\"b\":\"xray\",\"c\":\"xray\"}', 'COMPLETED', TIMESTAMP WITH TIME ZONE '2026-11-20 10:01:00+00',"
                    + " TIMESTAMP WITH TIME ZONE '2026-11-20 10:02:00+00')");
            s.execute("INSERT INTO task_event(task_id, at, kind, text) VALUES (97, TIMESTAMP WITH TIME ZONE '2026-11-20 10:02:00+00', 'task_completed', 'done')");
            s.execute("INSERT INTO setting VALUES ('submit-token', 'abc')");
        }
        try (TaskStore store = TaskStore.open(base)) {
            assertTrue(store.notice().startsWith("moved the H2 database " + dir.resolve("old.mv.db") + " into " + dir.resolve("old.db")), store.notice());
            assertEquals(TaskState.COMPLETED, store.task(97).orElseThrow().state());
            assertEquals("{\"a\":\"storage\",\"b\":\"xray\",\"c\":\"xray\"}", store.task(97).orElseThrow().args());
            assertEquals(Instant.parse("2026-11-20T10:01:00Z"), store.task(97).orElseThrow().submittedAt());
            assertEquals("GoTo", store.task(7).orElseThrow().task());
            assertEquals("task_completed", store.events(97).get(0).kind());
            assertEquals("abc", store.setting("submit-token").orElseThrow());
            assertTrue(store.insertTask("GoTo", "{}", Instant.now(), "submitted").id() > 97, "new ids follow the old ones");
        }
        assertTrue(Files.exists(dir.resolve("old.mv.db.migrated")));
        assertTrue(!Files.exists(dir.resolve("old.mv.db")));
        try (TaskStore again = TaskStore.open(base)) {
            assertEquals(null, again.notice(), "moved once");
            assertEquals(3, again.tasks(null, 10).size());
        }
    }

    /** The number of the 4096-byte page whose bytes hold {@code text}, or -1. */
    private static long pageHolding(byte[] file, String text) {
        byte[] needle = text.getBytes(java.nio.charset.StandardCharsets.UTF_8);
        outer:
        for (int i = 0; i + needle.length <= file.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (file[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i / 4096;
        }
        return -1;
    }
}
