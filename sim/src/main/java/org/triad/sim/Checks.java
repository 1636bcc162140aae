package org.triad.sim;

import java.util.Objects;

/** Fail-fast argument checks shared by the public API. */
final class Checks {
    private Checks() {
    }

    static double finite(String what, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(what + " must be a finite number, got " + v);
        }
        return v;
    }

    static double positive(String what, double v) {
        finite(what, v);
        if (v <= 0) {
            throw new IllegalArgumentException(what + " must be > 0, got " + v);
        }
        return v;
    }

    static double nonNegative(String what, double v) {
        finite(what, v);
        if (v < 0) {
            throw new IllegalArgumentException(what + " must be >= 0, got " + v);
        }
        return v;
    }

    static String name(String what, String s) {
        if (s == null || s.isBlank()) {
            throw new IllegalArgumentException(what + " must be a non-blank name, got " + (s == null ? "null" : "'" + s + "'"));
        }
        return s;
    }

    static <T> T notNull(String what, T o) {
        if (o == null) {
            throw new IllegalArgumentException(what + " must not be null");
        }
        return Objects.requireNonNull(o);
    }
}
