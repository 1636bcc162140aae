package org.triad.vda5050.devices;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentSkipListMap;

import org.triad.building.DeviceBoard;
import org.triad.vda5050.devices.DeviceMessages.DoorState;
import org.triad.vda5050.devices.DeviceMessages.LiftState;

/**
 * Every door and lift of the building as their states on the broker say (retained, so a watch started late sees them
 * at once): for the operator's view of the building ({@link DeviceBoard}). Reads only; asks nothing.
 */
public final class DeviceWatch implements AutoCloseable {
    private static final String DOOR_STATES = "triad/devices/v1/doors/+/state";
    private static final String LIFT_STATES = "triad/devices/v1/lifts/+/state";

    private final DeviceLink link;
    private final Map<String, DeviceBoard.Device> devices = new ConcurrentSkipListMap<>();

    /** Watches the device states on {@code link} (which it then owns and closes). */
    public DeviceWatch(DeviceLink link) {
        this.link = Objects.requireNonNull(link, "link");
        link.subscribe(DOOR_STATES, DoorState.class, s -> {
            if (s.doorName() != null && s.currentMode() != null) {
                devices.put("door/" + s.doorName(), new DeviceBoard.Device("door", s.doorName(), s.currentMode(), "", s.reason(), s.timestamp()));
            }
        });
        link.subscribe(LIFT_STATES, LiftState.class, s -> {
            if (s.liftName() != null && s.motionState() != null) {
                devices.put("lift/" + s.liftName(), new DeviceBoard.Device("lift", s.liftName(), s.motionState(), detail(s), s.reason(), s.timestamp()));
            }
        });
    }

    private static String detail(LiftState s) {
        StringBuilder b = new StringBuilder();
        if (s.currentFloor() != null) {
            b.append("at floor ").append(s.currentFloor());
        }
        if (s.destinationFloor() != null && !s.destinationFloor().equals(s.currentFloor())) {
            b.append(b.length() > 0 ? ", " : "").append(String.format(Locale.ROOT, "to floor %d", s.destinationFloor()));
        }
        if (s.doorMode() != null) {
            b.append(b.length() > 0 ? ", " : "").append("door ").append(s.doorMode());
        }
        return b.toString();
    }

    /** The devices heard of so far, by kind and name. */
    public List<DeviceBoard.Device> devices() {
        return List.copyOf(devices.values());
    }

    @Override
    public void close() {
        link.close();
    }
}
