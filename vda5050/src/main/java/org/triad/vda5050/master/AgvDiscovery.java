package org.triad.vda5050.master;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.regex.Pattern;

import com.fasterxml.jackson.databind.JsonNode;

import org.triad.vda5050.protocol.Messages.ConnectionState;

/**
 * Tracks the AGVs of one manufacturer on a {@link MasterControl}'s broker while a service runs, from the
 * {@code connection}, {@code factsheet} and {@code state} topics: an AGV that announces itself ONLINE,
 * publishes a factsheet naming every action the application needs and reports a state {@linkplain
 * Listener#appeared appears}; one whose connection is OFFLINE or CONNECTIONBROKEN for longer than the
 * reconnect grace (while this master is connected) is {@linkplain Listener#gone gone}, and {@linkplain
 * Listener#back back} once it reports a state again. An AGV whose serial number the configuration does not
 * allow, whose factsheet lacks an action, that publishes no factsheet or no state in time, or that the
 * application itself cannot use is {@linkplain Listener#refused refused} with the reason; it is looked at
 * again when it publishes another factsheet or announces itself anew. Checks run on one thread of their
 * own, every {@value #POLL_MILLIS} ms, so a silent AGV delays nobody.
 */
public final class AgvDiscovery implements AutoCloseable {
    public static final long POLL_MILLIS = 200;

    /** What the discovery reports, on its own thread, one call at a time. */
    public interface Listener {
        /**
         * A usable AGV, for the first time or after a refusal was lifted.
         *
         * @return why the application cannot use it after all (e.g. it stands on a node the building's map lacks), or empty to take it
         */
        Optional<String> appeared(RemoteAgv agv);

        /** The AGV is gone for {@code reason} (its last will, an OFFLINE, and for how long). */
        void gone(RemoteAgv agv, String reason);

        /** A gone AGV reports again. */
        void back(RemoteAgv agv);

        /** {@code serialNumber} of the manufacturer announced itself and cannot be used, for {@code reason}. */
        void refused(String serialNumber, String reason);
    }

    /**
     * What an AGV must be to join.
     *
     * @param manufacturer     whose AGVs are tracked (others on the broker are left alone)
     * @param allowedSerials   serial numbers allowed, {@code *} matching any characters; empty: any
     * @param actionTypes      action types the factsheet must list ({@code protocolFeatures.agvActions[].actionType})
     * @param factsheetSeconds how long after its ONLINE an AGV may take to publish its factsheet and first state
     * @param graceSeconds     how long an AGV may be OFFLINE or CONNECTIONBROKEN before it is gone (a broker restart
     *                         makes every AGV's last will arrive while the AGV is fine)
     */
    public record Requirements(String manufacturer, List<String> allowedSerials, Set<String> actionTypes, double factsheetSeconds,
            double graceSeconds) {
        public Requirements {
            Objects.requireNonNull(manufacturer, "manufacturer");
            allowedSerials = List.copyOf(allowedSerials);
            actionTypes = new TreeSet<>(actionTypes);
            if (!(factsheetSeconds > 0) || !(graceSeconds > 0)) {
                throw new IllegalArgumentException("factsheetSeconds and graceSeconds are positive, not " + factsheetSeconds + ", " + graceSeconds);
            }
        }

        boolean allows(String serial) {
            return allowedSerials.isEmpty() || allowedSerials.stream().anyMatch(p -> glob(p).matcher(serial).matches());
        }

        private static Pattern glob(String p) {
            StringBuilder b = new StringBuilder();
            String[] parts = p.split("\\*", -1);
            for (int i = 0; i < parts.length; i++) {
                if (i > 0) {
                    b.append(".*");
                }
                b.append(Pattern.quote(parts[i]));
            }
            return Pattern.compile(b.toString());
        }
    }

    private enum Phase { SEEN, REFUSED, PRESENT, GONE }

    private static final class Tracked {
        volatile Phase phase = Phase.SEEN;
        long seenNanos = System.nanoTime();
        JsonNode refusedFactsheet;
        boolean serialRefused;
        RemoteAgv agv;
        ConnectionState lastAnnounced = ConnectionState.ONLINE;
    }

    private final MasterControl master;
    private final Requirements requirements;
    private final Listener listener;
    private final Consumer<String> log;
    private final Map<String, Tracked> tracked = new ConcurrentHashMap<>();
    private final Thread thread;
    private volatile boolean running = true;

    /** Starts tracking at once, on a daemon thread of its own. */
    public AgvDiscovery(MasterControl master, Requirements requirements, Listener listener, Consumer<String> log) {
        this.master = Objects.requireNonNull(master, "master");
        this.requirements = Objects.requireNonNull(requirements, "requirements");
        this.listener = Objects.requireNonNull(listener, "listener");
        this.log = Objects.requireNonNull(log, "log");
        master.discovering();
        thread = new Thread(this::loop, "triad-vda-discovery");
        thread.setDaemon(true);
        thread.start();
    }

    private void loop() {
        while (running) {
            try {
                poll();
            } catch (RuntimeException e) {
                // a listener's fault must not end discovery: the next round looks again
                log.accept("vda5050: discovery: " + e);
            }
            try {
                Thread.sleep(POLL_MILLIS);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    /** One look at every AGV announced on the broker (also called by tests that want no thread timing). */
    void poll() {
        String prefix = requirements.manufacturer() + "/";
        master.announced().forEach((key, connection) -> {
            if (!key.startsWith(prefix)) {
                return;
            }
            String serial = key.substring(prefix.length());
            Tracked t = tracked.get(serial);
            if (t == null) {
                if (connection != ConnectionState.ONLINE) {
                    return; // the retained last word of an AGV that was gone before we came
                }
                t = new Tracked();
                tracked.put(serial, t);
                if (!requirements.allows(serial)) {
                    t.serialRefused = true;
                    refuse(serial, t, "serial number '" + serial + "' is not allowed by the configuration (allowed: "
                            + String.join(", ", requirements.allowedSerials()) + ")");
                    return;
                }
                t.agv = master.agv(requirements.manufacturer(), serial);
            }
            if (t.serialRefused) {
                return;
            }
            boolean reannounced = connection == ConnectionState.ONLINE && t.lastAnnounced != ConnectionState.ONLINE;
            t.lastAnnounced = connection;
            switch (t.phase) {
                case SEEN -> check(serial, t);
                case REFUSED -> {
                    JsonNode sheet = master.factsheet(requirements.manufacturer(), serial).orElse(null);
                    if (reannounced || sheet != null && !content(sheet).equals(content(t.refusedFactsheet))) {
                        t.phase = Phase.SEEN;
                        t.seenNanos = System.nanoTime();
                        check(serial, t);
                    }
                }
                case PRESENT -> {
                    double down = t.agv.secondsDown();
                    if (down > requirements.graceSeconds()) {
                        t.phase = Phase.GONE;
                        String why = String.format(Locale.ROOT, "AGV %s reported %s%s and did not come back within %.1f s", key,
                                t.agv.connection().map(Enum::name).orElse("nothing"),
                                t.agv.connection().orElse(null) == ConnectionState.CONNECTIONBROKEN ? " (its last will: the connection broke)" : "",
                                requirements.graceSeconds());
                        log.accept("vda5050: " + why);
                        listener.gone(t.agv, why);
                    }
                }
                case GONE -> {
                    if (t.agv.isOnline()) {
                        t.phase = Phase.PRESENT;
                        log.accept("vda5050: AGV " + key + " is back");
                        listener.back(t.agv);
                    }
                }
            }
        });
    }

    /** Checks a newly seen AGV: its factsheet, a first state, and whatever the application asks. */
    private void check(String serial, Tracked t) {
        double waited = (System.nanoTime() - t.seenNanos) / 1e9;
        Optional<JsonNode> sheet = master.factsheet(requirements.manufacturer(), serial);
        String topic = "uagv/v2/" + requirements.manufacturer() + "/" + serial;
        if (sheet.isEmpty()) {
            if (waited > requirements.factsheetSeconds()) {
                refuse(serial, t, String.format(Locale.ROOT, "it published no factsheet within %.1f s on %s/factsheet; the service needs one to"
                        + " know that it takes the actions %s", requirements.factsheetSeconds(), topic, requirements.actionTypes()));
            }
            return;
        }
        List<String> missing = missingActions(sheet.get());
        if (!missing.isEmpty()) {
            t.refusedFactsheet = sheet.get();
            refuse(serial, t, "its factsheet lacks the action" + (missing.size() == 1 ? " " : "s ") + String.join(", ", missing)
                    + " that the application needs (it lists " + listedActions(sheet.get()) + ")");
            return;
        }
        if (!t.agv.isOnline()) {
            if (waited > requirements.factsheetSeconds()) {
                t.refusedFactsheet = sheet.get();
                refuse(serial, t, String.format(Locale.ROOT, "it reported no state within %.1f s on %s/state", requirements.factsheetSeconds(), topic));
            }
            return;
        }
        Optional<String> unusable = listener.appeared(t.agv);
        if (unusable.isPresent()) {
            t.refusedFactsheet = sheet.get();
            refuse(serial, t, unusable.get());
            return;
        }
        t.phase = Phase.PRESENT;
        log.accept("vda5050: AGV " + requirements.manufacturer() + "/" + serial + " joined");
    }

    private void refuse(String serial, Tracked t, String reason) {
        t.phase = Phase.REFUSED;
        log.accept("vda5050: AGV " + requirements.manufacturer() + "/" + serial + " refused: " + reason);
        listener.refused(serial, reason);
    }

    /** A factsheet without its header's counter and time, which change each time the AGV publishes the same sheet. */
    private static JsonNode content(JsonNode sheet) {
        if (!(sheet instanceof com.fasterxml.jackson.databind.node.ObjectNode o)) {
            return sheet;
        }
        com.fasterxml.jackson.databind.node.ObjectNode c = o.deepCopy();
        c.remove("headerId");
        c.remove("timestamp");
        return c;
    }

    private List<String> missingActions(JsonNode sheet) {
        Set<String> listed = listedActions(sheet);
        List<String> missing = new ArrayList<>();
        for (String a : requirements.actionTypes()) {
            if (!listed.contains(a)) {
                missing.add(a);
            }
        }
        return missing;
    }

    private static Set<String> listedActions(JsonNode sheet) {
        Set<String> listed = new TreeSet<>();
        for (JsonNode a : sheet.path("protocolFeatures").path("agvActions")) {
            if (a.path("actionType").isTextual()) {
                listed.add(a.path("actionType").textValue());
            }
        }
        return listed;
    }

    /**
     * Whether every AGV announced so far has been decided on (joined or refused): a service that starts
     * with the AGVs already there waits for this (at most the factsheet time) rather than leave out one
     * that was a moment late with its first state.
     */
    public boolean settled() {
        String prefix = requirements.manufacturer() + "/";
        boolean unseen = master.announced().entrySet().stream()
                .anyMatch(e -> e.getKey().startsWith(prefix) && e.getValue() == ConnectionState.ONLINE && !tracked.containsKey(e.getKey().substring(prefix.length())));
        return !unseen && tracked.values().stream().noneMatch(t -> t.phase == Phase.SEEN);
    }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
    }
}
