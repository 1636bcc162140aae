package org.triad.vda5050.protocol;

import java.time.Instant;
import java.util.EnumMap;
import java.util.Map;

/** The sender's side of headerId: a counter per topic, starting at 0, incremented by each message sent on it. */
public final class HeaderIds {
    private final Map<Topic, Integer> next = new EnumMap<>(Topic.class);

    public synchronized int next(Topic topic) {
        int id = next.getOrDefault(topic, 0);
        next.put(topic, id + 1);
        return id;
    }

    /** A timestamp in the ISO 8601 UTC form the protocol requires. */
    public static String now() {
        return Instant.now().toString();
    }
}
