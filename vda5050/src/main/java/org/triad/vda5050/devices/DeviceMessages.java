package org.triad.vda5050.devices;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * The building's device protocol (in the spirit of Open-RMF's door and lift requests and states; not part of VDA
 * 5050): JSON on {@code triad/devices/v1/<doors|lifts>/<name>/request} (a client asks) and {@code .../state}
 * (the device answers, retained, on every change). A state names the request it last acted on, so a client
 * knows that its own request was served. Modes and states are upper-case strings; times are ISO-8601 UTC.
 */
public final class DeviceMessages {
    private DeviceMessages() {
    }

    /** Door modes. */
    public static final String OPEN = "OPEN";
    public static final String CLOSED = "CLOSED";
    /** A door between open and closed (closing waits for a clear doorway). */
    public static final String MOVING = "MOVING";
    /** A device that cannot do what was asked; its {@code reason} says why. */
    public static final String FAULT = "FAULT";
    /** A lift standing at a floor. */
    public static final String STOPPED = "STOPPED";

    /** Asks a door to open or close. */
    public record DoorRequest(String requestId, String requester, String doorName, String requestedMode, String timestamp) {
    }

    /** What a door is doing, and the request it last acted on ({@code reason} when it refuses one, e.g. locked). */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record DoorState(String doorName, String currentMode, String lastRequestId, String reason, String timestamp) {
    }

    /** Asks a lift to go to a floor (and open its door there). */
    public record LiftRequest(String requestId, String requester, String liftName, int destinationFloor, String timestamp) {
    }

    /**
     * Where a lift is: {@code currentFloor} (null between floors), {@code motionState} STOPPED, MOVING or FAULT (then
     * {@code reason}, e.g. stopped between floors), its door mode, and the request it last acted on.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    public record LiftState(String liftName, Integer currentFloor, Integer destinationFloor, String motionState, String doorMode,
            String lastRequestId, String reason, String timestamp) {
    }

    /** {@code triad/devices/v1/doors/<name>/request}. */
    public static String doorRequestTopic(String door) {
        return "triad/devices/v1/doors/" + name(door) + "/request";
    }

    public static String doorStateTopic(String door) {
        return "triad/devices/v1/doors/" + name(door) + "/state";
    }

    public static String liftRequestTopic(String lift) {
        return "triad/devices/v1/lifts/" + name(lift) + "/request";
    }

    public static String liftStateTopic(String lift) {
        return "triad/devices/v1/lifts/" + name(lift) + "/state";
    }

    private static String name(String n) {
        if (n == null || !n.matches("[A-Za-z0-9_.-]{1,100}")) {
            throw new IllegalArgumentException("a device name is 1..100 letters, digits, '_', '.' or '-', not '" + n + "'");
        }
        return n;
    }
}
