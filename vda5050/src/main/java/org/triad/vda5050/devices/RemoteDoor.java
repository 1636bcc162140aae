package org.triad.vda5050.devices;

import java.time.Instant;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

import org.triad.vda5050.devices.DeviceMessages.DoorRequest;
import org.triad.vda5050.devices.DeviceMessages.DoorState;

/**
 * A door of the building as a world action's implementation sees it: {@link #open()} and {@link #close()} publish a
 * request and wait until the door's state names that request with the mode asked for. A door that refuses (its state
 * carries a reason), or does not answer within the timeout, makes the call return false with the reason in
 * {@link #lastFailure()}: never a hang.
 */
public final class RemoteDoor {
    private final DeviceLink link;
    private final String door;
    private final String requester;
    private final double timeoutSeconds;
    private final Object lock = new Object();
    private DoorState state;
    private String lastFailure;

    /**
     * @param requester      who asks (a robot's serial number), for the device's log
     * @param timeoutSeconds wall-clock seconds to wait for the door to do what was asked (&gt; 0)
     */
    public RemoteDoor(DeviceLink link, String door, String requester, double timeoutSeconds) {
        this.link = Objects.requireNonNull(link, "link");
        this.door = Objects.requireNonNull(door, "door");
        this.requester = Objects.requireNonNull(requester, "requester");
        if (!(timeoutSeconds > 0) || Double.isInfinite(timeoutSeconds)) {
            throw new IllegalArgumentException("a door's timeout is a positive number of seconds, not " + timeoutSeconds);
        }
        this.timeoutSeconds = timeoutSeconds;
        link.subscribe(DeviceMessages.doorStateTopic(door), DoorState.class, s -> {
            synchronized (lock) {
                state = s;
                lock.notifyAll();
            }
        });
    }

    /** Asks the door to open; true once it reports OPEN for this request. */
    public boolean open() {
        return request(DeviceMessages.OPEN);
    }

    /** Asks the door to close; true once it reports CLOSED for this request (it waits for a clear doorway). */
    public boolean close() {
        return request(DeviceMessages.CLOSED);
    }

    /** The door's last reported state, if it ever reported one. */
    public Optional<DoorState> state() {
        synchronized (lock) {
            return Optional.ofNullable(state);
        }
    }

    /** Why the last request failed. */
    public Optional<String> lastFailure() {
        synchronized (lock) {
            return Optional.ofNullable(lastFailure);
        }
    }

    private boolean request(String mode) {
        String id = UUID.randomUUID().toString();
        link.publish(DeviceMessages.doorRequestTopic(door), new DoorRequest(id, requester, door, mode, Instant.now().toString()), false);
        long deadline = System.nanoTime() + (long) (timeoutSeconds * 1e9);
        synchronized (lock) {
            while (true) {
                if (state != null && id.equals(state.lastRequestId())) {
                    if (mode.equals(state.currentMode())) {
                        lastFailure = null;
                        return true;
                    }
                    if (state.reason() != null) {
                        lastFailure = "door '" + door + "' refused " + mode + ": " + state.reason();
                        return false;
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    lastFailure = String.format(Locale.ROOT, "door '%s' did not answer the request %s within %.1f s%s", door, mode,
                            timeoutSeconds, state == null ? " (it never reported a state: is the device online?)"
                                    : " (last state " + state.currentMode() + ")");
                    return false;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    lastFailure = "interrupted while waiting for door '" + door + "'";
                    return false;
                }
            }
        }
    }
}
