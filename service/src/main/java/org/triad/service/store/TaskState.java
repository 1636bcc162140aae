package org.triad.service.store;

import java.util.Locale;

/** Where a task is in its life; a task is never deleted, only ends in a final state. */
public enum TaskState {
    /** Waiting for a robot (also after a retry, a re-assignment, an interruption). */
    QUEUED,
    /** A robot's RefArc executes it. */
    RUNNING,
    COMPLETED,
    /** RefArc gave up; a remote-operation request waits for the operator. */
    ABORTED,
    CANCELLED,
    /** The operator marked it done by hand. */
    DONE,
    /**
     * Not executed: it waited for an object another task held, and when that task ended the task's
     * outcome (its last goal) already held for the robot that would have run it; the reason names the task.
     */
    REFUSED;

    public String json() {
        return name().toLowerCase(Locale.ROOT);
    }

    public boolean isFinal() {
        return this == COMPLETED || this == CANCELLED || this == DONE || this == REFUSED;
    }

    public static TaskState fromJson(String s) {
        for (TaskState t : values()) {
            if (t.json().equals(s)) {
                return t;
            }
        }
        throw new IllegalArgumentException("no task state '" + s + "'; states are queued, running, completed, aborted, cancelled, done, refused");
    }
}
