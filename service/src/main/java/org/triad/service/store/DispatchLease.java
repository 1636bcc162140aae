package org.triad.service.store;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;

/**
 * Which service instance dispatches. On the embedded file there is one instance (the file is locked),
 * so it always holds the lease. On PostgreSQL the lease is a session advisory lock on a connection of
 * its own: the server releases it the moment that session ends, which is when the holder's process
 * dies (its socket closes) or its connection is lost, and a standby instance polling every
 * {@link #POLL_MILLIS} ms takes it over.
 */
public abstract class DispatchLease implements AutoCloseable {
    /** How often a standby tries to take the lease and the holder checks it still has it. */
    public static final long POLL_MILLIS = 500;
    /** The advisory lock's key: "triad" dispatch, one per database. */
    static final long KEY = 0x7472696164L;

    /** Whether this instance may dispatch now: takes the lease if free, confirms it if held. */
    public abstract boolean holds();

    @Override
    public abstract void close();

    public static DispatchLease of(Database db) {
        return db.shared() ? new Advisory(db) : new Sole();
    }

    private static final class Sole extends DispatchLease {
        @Override
        public boolean holds() {
            return true;
        }

        @Override
        public void close() {
            // nothing to release
        }
    }

    private static final class Advisory extends DispatchLease {
        private final Database db;
        private Connection connection;
        private boolean held;

        Advisory(Database db) {
            this.db = db;
        }

        @Override
        public synchronized boolean holds() {
            try {
                if (connection == null) {
                    held = false;
                    connection = db.connect();
                }
                try (Statement s = connection.createStatement()) {
                    s.setQueryTimeout(5);
                    if (held) {
                        // the session is alive, so the lock it holds is too
                        s.execute("SELECT 1");
                    } else {
                        try (ResultSet r = s.executeQuery("SELECT pg_try_advisory_lock(" + KEY + ")")) {
                            r.next();
                            held = r.getBoolean(1);
                        }
                    }
                }
                return held;
            } catch (SQLException e) {
                drop();
                return false;
            }
        }

        private void drop() {
            held = false;
            if (connection != null) {
                try {
                    connection.close();
                } catch (SQLException ignored) {
                    // a broken session is gone anyway, and its lock with it
                }
            }
            connection = null;
        }

        @Override
        public synchronized void close() {
            drop();
        }
    }
}
