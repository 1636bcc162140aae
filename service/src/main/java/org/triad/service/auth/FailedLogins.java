package org.triad.service.auth;

import java.time.Duration;
import java.time.Instant;

/**
 * Records failed logins in the audit log, at most {@value #PER_MINUTE} a minute so that a flood of bad
 * tokens cannot fill the database: the rest are counted, and the count is recorded with the next entry.
 * A presented token is never recorded, only the user name it claims ({@code NAME.} of {@code NAME.SECRET}).
 */
public final class FailedLogins {
    static final int PER_MINUTE = 60;

    private final AuditLog audit;
    private Instant windowStart = Instant.EPOCH;
    private int inWindow;
    private long suppressed;

    public FailedLogins(AuditLog audit) {
        this.audit = audit;
    }

    public synchronized void record(String presentedToken, String where, Instant now) {
        if (Duration.between(windowStart, now).compareTo(Duration.ofMinutes(1)) >= 0) {
            windowStart = now;
            inWindow = 0;
        }
        if (inWindow >= PER_MINUTE) {
            suppressed++;
            return;
        }
        inWindow++;
        int dot = presentedToken.lastIndexOf('.');
        String claimed = dot > 0 && dot <= 64 && presentedToken.substring(0, dot).matches("[a-z0-9_-]+") ? presentedToken.substring(0, dot) : "?";
        String more = suppressed > 0 ? " (and " + suppressed + " more failed logins not recorded one by one before this)" : "";
        suppressed = 0;
        audit.record(claimed, "login-failed", where + more, now);
    }
}
