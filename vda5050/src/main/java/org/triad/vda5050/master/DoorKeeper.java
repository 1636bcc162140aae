package org.triad.vda5050.master;

import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.UUID;
import java.time.Instant;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;

import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.devices.DeviceMessages.DoorRequest;
import org.triad.vda5050.devices.RemoteDoor;

/**
 * The building's doors tied to traffic control's door reservations: the robot granted a stretch through a door
 * has the door opened (over the device protocol, {@link RemoteDoor}) before its base is extended through it, and
 * the door is asked to close only once no robot holds its reservation or waits for a stretch through it, so a
 * door opened for one robot is not closed on the next one in line. Doors no robot went through are left as they are.
 *
 * <p>It keeps only the doors it is given, and of those only the ones the building serves as devices (that have
 * reported a state): a door without a device is left as it is, as before. Opening waits for the door to report
 * OPEN; a door that refuses (locked) or does not answer within the timeout fails the robot's action with that
 * reason (RefArc re-plans). Closing does not hold anybody up: it runs on a thread of its own, and a door that
 * cannot close at once (someone stands in its doorway) closes as soon as the doorway is clear.
 */
public final class DoorKeeper implements AutoCloseable {
    private final Map<String, RemoteDoor> doors = new LinkedHashMap<>();
    private final Map<String, Object> opening = new LinkedHashMap<>();
    /** Doors with a close on its way (at most one each). */
    private final Set<String> closing = new HashSet<>();
    /** Doors asked to close since they were last opened (guarded by the door's lock): the next robot has it opened again. */
    private final Set<String> closeSent = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private final DeviceLink link;
    /** Doors a robot was let through since they were last asked to close: the ones to close once nobody needs them. */
    private final Set<String> used = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private final Set<String> reportedNoDevice = new HashSet<>();
    private final Consumer<String> log;
    private final ExecutorService closer = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "traffic-door-closer");
        t.setDaemon(true);
        return t;
    });

    /**
     * @param doors          the doors traffic control keeps (their names are the device names and the ids of the map's
     *                       door areas); not a fire door, which is closed for a reason a robot must not override
     * @param timeoutSeconds how long a door may take to open or close (&gt; 0)
     * @param log            where one-line reports go
     */
    public DoorKeeper(DeviceLink link, Collection<String> doors, double timeoutSeconds, Consumer<String> log) {
        this.link = Objects.requireNonNull(link, "link");
        this.log = Objects.requireNonNull(log, "log");
        for (String d : doors) {
            this.doors.put(d, new RemoteDoor(link, d, "traffic-control", timeoutSeconds));
            opening.put(d, new Object());
        }
    }

    /** The doors it keeps. */
    public Set<String> doors() {
        return doors.keySet();
    }

    /**
     * Opens each kept door of {@code names} for {@code robot} and waits until it reports OPEN; the reason when one
     * refuses or does not answer. Called without traffic control's lock (it may wait for the door).
     */
    Optional<String> open(String robot, Collection<String> names) {
        for (String name : names) {
            RemoteDoor door = doors.get(name);
            if (door == null) {
                continue;
            }
            if (door.state().isEmpty()) {
                synchronized (this) {
                    if (reportedNoDevice.add(name)) {
                        log.accept("traffic: door '" + name + "' has reported no state (no device serves it): traffic control does not open or close it");
                    }
                }
                continue;
            }
            synchronized (opening.get(name)) { // one request at a time per door: its answer names the request
                used.add(name);
                boolean open = door.state().map(s -> DeviceMessages.OPEN.equals(s.currentMode())).orElse(false);
                if (open && !closeSent.contains(name)) {
                    continue;
                }
                if (!door.open()) {
                    return Optional.of("traffic control could not open " + name + " for " + robot + ": " + door.lastFailure().orElse("no answer"));
                }
                closeSent.remove(name);
                log.accept("traffic: door '" + name + "' opened for " + robot);
            }
        }
        return Optional.empty();
    }

    /**
     * Asks the door to close, unless {@code stillNeeded} says a robot holds or waits for it by the time the request
     * goes out. Called under traffic control's lock: the request is sent from another thread.
     */
    void closeIfUnneeded(String name, java.util.function.BooleanSupplier stillNeeded) {
        RemoteDoor door = doors.get(name);
        if (door == null || !used.contains(name) || door.state().isEmpty() || closeSent.contains(name)
                || door.state().map(s -> DeviceMessages.CLOSED.equals(s.currentMode())).orElse(false)) {
            return;
        }
        synchronized (this) {
            if (!closing.add(name)) {
                return; // a close is on its way: it checks again before it is sent
            }
        }
        try {
            closer.execute(() -> closeNow(name, stillNeeded));
        } catch (java.util.concurrent.RejectedExecutionException closed) { // the fleet is closing: the doors stay as they are
            synchronized (this) {
                closing.remove(name);
            }
        }
    }

    /** Runs on a closer thread: a second look under the door's lock, then the request. */
    private void closeNow(String name, java.util.function.BooleanSupplier stillNeeded) {
        try {
            synchronized (opening.get(name)) { // sent under the door's lock: an open request for the next robot follows it
                if (stillNeeded.getAsBoolean() || closeSent.contains(name)) {
                    return;
                }
                link.publish(DeviceMessages.doorRequestTopic(name), new DoorRequest(UUID.randomUUID().toString(), "traffic-control", name,
                        DeviceMessages.CLOSED, Instant.now().toString()), false);
                closeSent.add(name);
                used.remove(name);
            }
            log.accept("traffic: door '" + name + "' asked to close: no robot holds or waits for it");
        } finally {
            synchronized (this) {
                closing.remove(name);
            }
        }
    }

    @Override
    public void close() {
        closer.shutdownNow();
    }
}
