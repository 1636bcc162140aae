package org.triad.vda5050.devices;

import java.time.Instant;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

import org.triad.vda5050.devices.DeviceMessages.LiftRequest;
import org.triad.vda5050.devices.DeviceMessages.LiftState;

/**
 * A lift of the building as a world action's implementation (or master control) sees it: {@link #call(int)} publishes
 * a request and waits until the lift's state names that request and reports the cabin STOPPED at the floor with its
 * door OPEN. A lift in FAULT (stopped between floors; its state's {@code reason}), a request it refuses, or no answer
 * within the timeout makes the call return false with the reason in {@link #lastFailure()}: never a hang.
 */
public final class RemoteLift {
    private final DeviceLink link;
    private final String lift;
    private final String requester;
    private final double timeoutSeconds;
    private final Object lock = new Object();
    private LiftState state;
    private String lastFailure;

    /**
     * @param requester      who asks (a robot's serial number), for the device's log
     * @param timeoutSeconds wall-clock seconds to wait for the cabin to stand open at the floor (&gt; 0): allow for the
     *                       ride and the door
     */
    public RemoteLift(DeviceLink link, String lift, String requester, double timeoutSeconds) {
        this.link = Objects.requireNonNull(link, "link");
        this.lift = Objects.requireNonNull(lift, "lift");
        this.requester = Objects.requireNonNull(requester, "requester");
        if (!(timeoutSeconds > 0) || Double.isInfinite(timeoutSeconds)) {
            throw new IllegalArgumentException("a lift's timeout is a positive number of seconds, not " + timeoutSeconds);
        }
        this.timeoutSeconds = timeoutSeconds;
        link.subscribe(DeviceMessages.liftStateTopic(lift), LiftState.class, s -> {
            synchronized (lock) {
                state = s;
                lock.notifyAll();
            }
        });
    }

    public String name() {
        return lift;
    }

    /**
     * Calls the cabin to {@code floor}; true once the lift reports, for this request, STOPPED at that floor with its
     * door OPEN. False (see {@link #lastFailure()}) when it reports FAULT or refuses, or does not get there in time.
     */
    public boolean call(int floor) {
        String id = UUID.randomUUID().toString();
        link.publish(DeviceMessages.liftRequestTopic(lift), new LiftRequest(id, requester, lift, floor, Instant.now().toString()), false);
        long deadline = System.nanoTime() + (long) (timeoutSeconds * 1e9);
        synchronized (lock) {
            while (true) {
                if (state != null && id.equals(state.lastRequestId())) {
                    if (DeviceMessages.FAULT.equals(state.motionState())) {
                        String why = state.reason() != null ? state.reason() : "FAULT";
                        lastFailure = why.contains("lift '" + lift + "'") ? why : "lift '" + lift + "': " + why;
                        return false;
                    }
                    if (DeviceMessages.STOPPED.equals(state.motionState()) && Integer.valueOf(floor).equals(state.currentFloor())
                            && DeviceMessages.OPEN.equals(state.doorMode())) {
                        lastFailure = null;
                        return true;
                    }
                    if (state.reason() != null) {
                        lastFailure = "lift '" + lift + "' refused floor " + floor + ": " + state.reason();
                        return false;
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    lastFailure = String.format(Locale.ROOT, "lift '%s' did not answer the request for floor %d within %.1f s%s", lift, floor,
                            timeoutSeconds, state == null ? " (it never reported a state: is the device online?)"
                                    : " (last state " + state.motionState() + " at floor " + state.currentFloor() + ", door " + state.doorMode() + ")");
                    return false;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    lastFailure = "interrupted while waiting for lift '" + lift + "'";
                    return false;
                }
            }
        }
    }

    /** The lift's last reported state, if it ever reported one. */
    public Optional<LiftState> state() {
        synchronized (lock) {
            return Optional.ofNullable(state);
        }
    }

    /** Why the last call failed. */
    public Optional<String> lastFailure() {
        synchronized (lock) {
            return Optional.ofNullable(lastFailure);
        }
    }
}
