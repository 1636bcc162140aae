package org.triad.service.auth;

import java.util.Locale;

/**
 * What a user may do: staff submit, follow and cancel tasks; an operator also retries, re-assigns, marks
 * done and takes robots offline, and reads the audit log; an admin also manages users.
 */
public enum Role {
    STAFF, OPERATOR, ADMIN;

    /** Whether this role may do what {@code needed} may. */
    public boolean allows(Role needed) {
        return ordinal() >= needed.ordinal();
    }

    /** {@code staff}, {@code operator}, {@code admin}. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The role named {@code staff}, {@code operator} or {@code admin}. */
    public static Role of(String label) {
        for (Role r : values()) {
            if (r.label().equals(label)) {
                return r;
            }
        }
        throw new IllegalArgumentException("a role is staff, operator or admin, not '" + label + "'");
    }
}
