package org.triad.examples.hospital.vda5050;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

import org.triad.examples.hospital.HospitalBuilding;
import org.triad.sim.Door;
import org.triad.sim.Simulation;
import org.triad.sim.SimulationClock;
import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.DeviceMessages;
import org.triad.vda5050.devices.DeviceMessages.DoorRequest;
import org.triad.vda5050.devices.DeviceMessages.DoorState;

/**
 * The building's doors as devices on the broker ({@link DeviceMessages}): a request to open or close a door of the
 * simulation is queued on the building's clock and executed there (closing waits for a clear doorway: MOVING until
 * then); the door's state is published (retained) when served and whenever the door opens or closes, naming the
 * request it last acted on. A locked door refuses with the reason.
 */
public final class BuildingDoors {
    private final DeviceLink link;
    private final SimulationClock clock;
    private final Map<String, String> lastRequest = new LinkedHashMap<>();
    private final Map<String, String> published = new LinkedHashMap<>();

    private BuildingDoors(DeviceLink link, SimulationClock clock) {
        this.link = link;
        this.clock = clock;
    }

    /** Serves every door of the running building on {@code link}. */
    public static BuildingDoors serve(HospitalBuilding building, DeviceLink link) {
        Objects.requireNonNull(link, "link");
        SimulationClock clock = building.clock().orElseThrow(() -> new IllegalStateException("start the building's clock first"));
        BuildingDoors doors = new BuildingDoors(link, clock);
        clock.run(s -> {
            for (Door d : s.doors()) {
                if (!isLandingDoor(d.name())) {
                    doors.publish(d, null);
                }
            }
            s.addStepListener(() -> doors.publishChanges(s));
        });
        for (Door d : clock.call(Simulation::doors)) {
            String name = d.name();
            if (isLandingDoor(name)) {
                continue; // a lift's landing door opens and closes with its cabin (BuildingLifts), not on request
            }
            link.subscribe(DeviceMessages.doorRequestTopic(name), DoorRequest.class, r -> clock.submit(s -> doors.handle(s, name, r)));
        }
        return doors;
    }

    /** Runs on the clock thread. */
    private void handle(Simulation s, String name, DoorRequest r) {
        Door d = s.door(name);
        lastRequest.put(name, r.requestId());
        if (!DeviceMessages.OPEN.equals(r.requestedMode()) && !DeviceMessages.CLOSED.equals(r.requestedMode())) {
            publish(d, "requestedMode must be OPEN or CLOSED, not '" + r.requestedMode() + "'");
            return;
        }
        if (d.isLocked()) {
            publish(d, "door '" + name + "' is locked");
            return;
        }
        if (DeviceMessages.OPEN.equals(r.requestedMode())) {
            s.openDoor(name);
        } else {
            s.closeDoor(name);
        }
        publish(d, null);
    }

    /** Runs on the clock thread after every step: a door that opened or closed since its last state is published. */
    private void publishChanges(Simulation s) {
        for (Door d : s.doors()) {
            if (!isLandingDoor(d.name()) && !mode(d).equals(published.get(d.name()))) {
                publish(d, null);
            }
        }
    }

    /** The names of the doors served here (every door of the building but the lifts' landing doors). */
    public static java.util.List<String> served(SimulationClock clock) {
        return clock.call(s -> s.doors().stream().map(Door::name).filter(n -> !isLandingDoor(n)).toList());
    }

    private static boolean isLandingDoor(String name) {
        return org.triad.examples.hospital.HospitalFloor.LIFT_LANDINGS.stream().anyMatch(l -> l.door().equals(name));
    }

    private static String mode(Door d) {
        return d.isOpen() ? (d.isClosing() ? DeviceMessages.MOVING : DeviceMessages.OPEN) : DeviceMessages.CLOSED;
    }

    private void publish(Door d, String reason) {
        String mode = mode(d);
        published.put(d.name(), mode);
        link.publish(DeviceMessages.doorStateTopic(d.name()), new DoorState(d.name(), mode, lastRequest.get(d.name()), reason,
                Instant.now().toString()), true);
    }
}
