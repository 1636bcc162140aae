package org.triad.service;

import java.util.Optional;
import java.util.Properties;

/**
 * How many robots of the fleet run tasks at once, from the application's {@code META-INF/triad/application.properties}
 * ({@code dispatch.atOnce=N}): a building whose corridors carry only so many robots before they wait for each other
 * more than they drive says so here; the others stay where they are (parked) until one of the working robots is done.
 * A charging task is not held back by it. None set: every idle robot takes work.
 *
 * @param robots the most robots running a task at the same time, at least 1
 */
public record DispatchLimit(int robots) {
    public DispatchLimit {
        if (robots < 1) {
            throw new IllegalArgumentException("dispatch.atOnce is at least 1 robot, not " + robots);
        }
    }

    /** The limit the application's properties on this class loader set, if any; a malformed one is a start-up error. */
    public static Optional<DispatchLimit> of(ClassLoader loader) {
        return ApplicationProperties.read(loader).flatMap(a -> of(a.values(), a.where()));
    }

    static Optional<DispatchLimit> of(Properties p, String where) {
        String value = p.getProperty("dispatch.atOnce");
        if (value == null) {
            return Optional.empty();
        }
        int n;
        try {
            n = Integer.parseInt(value.trim());
        } catch (NumberFormatException e) {
            n = 0;
        }
        if (n < 1) {
            throw ServiceError.startup(where + ": dispatch.atOnce takes a whole number of robots, at least 1, not '" + value + "'");
        }
        return Optional.of(new DispatchLimit(n));
    }
}
