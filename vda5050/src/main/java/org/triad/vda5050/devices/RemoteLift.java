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
    /** The request a call waits for, its floor, and the first state that answered it (null while none has). */
    private String awaited;
    private int awaitedFloor;
    private LiftState answer;

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
                // kept: the lift may serve a queued request right after this one's, and its next state names that one
                if (awaited != null && awaited.equals(s.lastRequestId()) && answer == null && answers(s, awaitedFloor)) {
                    answer = s;
                }
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
        synchronized (lock) {
            awaited = id;
            awaitedFloor = floor;
            answer = null;
        }
        link.publish(DeviceMessages.liftRequestTopic(lift), new LiftRequest(id, requester, lift, floor, Instant.now().toString()), false);
        long deadline = System.nanoTime() + (long) (timeoutSeconds * 1e9);
        synchronized (lock) {
            while (true) {
                LiftState a = answer;
                if (a != null) {
                    awaited = null;
                    if (DeviceMessages.FAULT.equals(a.motionState())) {
                        String why = a.reason() != null ? a.reason() : "FAULT";
                        lastFailure = why.contains("lift '" + lift + "'") ? why : "lift '" + lift + "': " + why;
                        return false;
                    }
                    if (DeviceMessages.STOPPED.equals(a.motionState()) && Integer.valueOf(floor).equals(a.currentFloor())
                            && DeviceMessages.OPEN.equals(a.doorMode())) {
                        lastFailure = null;
                        return true;
                    }
                    lastFailure = "lift '" + lift + "' refused floor " + floor + ": " + a.reason();
                    return false;
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    awaited = null;
                    lastFailure = String.format(Locale.ROOT, "lift '%s' did not answer the request for floor %d within %.1f s%s", lift, floor,
                            timeoutSeconds, state == null ? " (it never reported a state: is the device online?)"
                                    : " (last state " + state.motionState() + " at floor " + state.currentFloor() + ", door " + state.doorMode() + ")");
                    return false;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    awaited = null;
                    lastFailure = "interrupted while waiting for lift '" + lift + "'";
                    return false;
                }
            }
        }
    }

    /** Whether a state naming the awaited request ends the call: FAULT, a refusal (a reason), or the cabin open at {@code floor}. */
    private static boolean answers(LiftState s, int floor) {
        return DeviceMessages.FAULT.equals(s.motionState()) || s.reason() != null
                || DeviceMessages.STOPPED.equals(s.motionState()) && Integer.valueOf(floor).equals(s.currentFloor()) && DeviceMessages.OPEN.equals(s.doorMode());
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
