package org.triad.service.store;

import java.time.Instant;

/** The rows of the service's database. */
public final class Records {
    private Records() {
    }

    /** {@code priority}: higher is dispatched first (0 unless the submission said otherwise). */
    public record TaskRow(long id, String task, String args, TaskState state, String robot, String preferredRobot, String reason,
            Instant submittedAt, Instant updatedAt, int priority) {
    }

    public record EventRow(long id, long taskId, Instant at, String kind, String robot, String text) {
    }

    public record RequestRow(long id, long taskId, String robot, String goal, String reason, Instant raisedAt, Instant resolvedAt,
            String resolution) {
    }
}
