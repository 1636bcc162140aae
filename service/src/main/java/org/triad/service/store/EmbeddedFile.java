package org.triad.service.store;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.triad.service.ServiceError;

/**
 * The embedded database's files: {@code NAME.db} (SQLite, with its {@code -wal} and {@code -shm}),
 * {@code NAME.db.lock} (held while a service uses it, so that a second process is told so instead of
 * sharing the queue), and {@code NAME.mv.db}, the H2 file of earlier versions, migrated on first start.
 */
public final class EmbeddedFile {
    /** How the user recovers a damaged database; printed with every damage report. */
    public static final String RECOVERY_OPTION = "--recover";
    private static final byte[] SQLITE_HEADER = "SQLite format 3\0".getBytes(java.nio.charset.StandardCharsets.US_ASCII);

    private final Path file;
    private final Path legacyH2;
    private FileChannel lockChannel;
    private FileLock lock;

    private EmbeddedFile(Path file, Path legacyH2) {
        this.file = file;
        this.legacyH2 = legacyH2;
    }

    /** {@code P.db} for a path {@code P} without that ending; {@code NAME.mv.db} names the H2 file whose data moves to {@code NAME.db}. */
    static EmbeddedFile of(Path path) {
        Path p = path.toAbsolutePath().normalize();
        String name = p.getFileName().toString();
        String base = name.endsWith(".mv.db") ? name.substring(0, name.length() - ".mv.db".length())
                : name.endsWith(".db") ? name.substring(0, name.length() - ".db".length()) : name;
        return new EmbeddedFile(p.resolveSibling(base + ".db"), p.resolveSibling(base + ".mv.db"));
    }

    public Path file() {
        return file;
    }

    Path legacyH2() {
        return legacyH2;
    }

    /** Checks the folder and takes the lock; throws a start-up error naming the problem. */
    void prepare() {
        Path folder = file.getParent();
        if (folder != null && !Files.isDirectory(folder)) {
            throw ServiceError.startup("database " + file + ": the folder " + folder + " does not exist");
        }
        if (Files.exists(file) && !Files.isWritable(file)) {
            throw ServiceError.startup("database " + file + " is read-only: the service must write every task it accepts");
        }
        if (!Files.exists(file) && folder != null && !Files.isWritable(folder)) {
            throw ServiceError.startup("database " + file + " cannot be created: the folder " + folder + " is read-only");
        }
        Path lockFile = file.resolveSibling(file.getFileName() + ".lock");
        try {
            lockChannel = FileChannel.open(lockFile, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            try {
                lock = lockChannel.tryLock();
            } catch (OverlappingFileLockException e) {
                lock = null;
            }
        } catch (IOException e) {
            throw ServiceError.startup("database " + file + ": cannot create its lock file " + lockFile + ": " + e.getMessage());
        }
        if (lock == null) {
            release();
            throw ServiceError.startup("database " + file + ": in use by another process (is another 'triad serve' running on it?)");
        }
    }

    void release() {
        try {
            if (lock != null) {
                lock.release();
            }
            if (lockChannel != null) {
                lockChannel.close();
            }
        } catch (IOException e) {
            // the lock goes with the process anyway
        }
        lock = null;
        lockChannel = null;
    }

    /**
     * Refuses a file that is not a SQLite database, fails SQLite's integrity check, or has lost its
     * schema: the service never starts on damage as if the queue were empty.
     */
    void check(Database db) {
        if (!Files.exists(file)) {
            return;
        }
        try {
            if (Files.size(file) == 0) {
                return;
            }
            byte[] head = new byte[SQLITE_HEADER.length];
            try (var in = Files.newInputStream(file)) {
                int n = in.readNBytes(head, 0, head.length);
                if (n < head.length || !Arrays.equals(head, SQLITE_HEADER)) {
                    throw damaged("not a SQLite database (its first bytes are not SQLite's header)");
                }
            }
        } catch (IOException e) {
            throw ServiceError.startup("database " + file + " cannot be read: " + e.getMessage());
        }
        try (Connection c = db.connect(); Statement s = c.createStatement()) {
            List<String> problems = new ArrayList<>();
            try (ResultSet r = s.executeQuery("PRAGMA integrity_check(20)")) {
                while (r.next()) {
                    problems.add(r.getString(1));
                }
            }
            if (!(problems.size() == 1 && problems.get(0).equals("ok"))) {
                throw damaged("SQLite's integrity check finds " + String.join("; ", problems));
            }
            try (ResultSet r = s.executeQuery("SELECT COUNT(*) FROM sqlite_master WHERE type = 'table' AND name = 'flyway_schema_history'")) {
                r.next();
                if (r.getInt(1) == 0) {
                    throw damaged("it has no schema history: not a Triad service database, or its schema was lost");
                }
            }
        } catch (SQLException e) {
            throw damaged(e.getMessage() == null ? e.toString() : e.getMessage().lines().findFirst().orElse(""));
        }
    }

    private ServiceError damaged(String why) {
        return ServiceError.startup("database " + file + " is damaged: " + why + ". Nothing was changed. Recover what can be read with"
                + " 'triad serve ... --db " + file + " " + RECOVERY_OPTION + "' (every readable row goes into a new " + file.getFileName()
                + "; the damaged file is kept as " + file.getFileName() + ".damaged-TIME), or restore a backup");
    }
}
