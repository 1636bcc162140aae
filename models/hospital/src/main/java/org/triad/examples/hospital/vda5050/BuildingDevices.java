package org.triad.examples.hospital.vda5050;

import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import org.triad.vda5050.devices.DeviceLink;
import org.triad.vda5050.devices.RemoteDoor;
import org.triad.vda5050.devices.RemoteLift;
import org.triad.vda5050.master.MasterControl;

/**
 * The building's doors and lifts as one robot's world binding reaches them: over the device protocol on its master
 * control's connection ({@link DeviceLink#over}), so on a secured broker as master control's identity, which the ACL
 * lets ask doors and lifts; subscribed when a door or lift is first needed.
 */
final class BuildingDevices implements AutoCloseable {
    /** Wall-clock seconds to wait for the building to open (or close) a door. */
    static final double DOOR_SECONDS = 10;
    /** Wall-clock seconds to wait for a lift to stand open at a floor: a ride of 8 simulated seconds per floor at 1x, and margin. */
    static final double LIFT_SECONDS = 60;

    private final MasterControl master;
    private final String requester;
    private final double doorSeconds;
    private final double liftSeconds;
    private final Consumer<String> problems;
    private final Map<String, RemoteDoor> doors = new ConcurrentHashMap<>();
    private final Map<String, RemoteLift> lifts = new ConcurrentHashMap<>();
    private DeviceLink link;
    private boolean closed;

    BuildingDevices(MasterControl master, String requester, double doorSeconds, double liftSeconds, Consumer<String> problems) {
        this.master = Objects.requireNonNull(master, "master");
        this.requester = Objects.requireNonNull(requester, "requester");
        this.doorSeconds = doorSeconds;
        this.liftSeconds = liftSeconds;
        this.problems = Objects.requireNonNull(problems, "problems");
    }

    /** @throws RuntimeException (with the reason) when the broker cannot be reached for the devices */
    RemoteDoor door(String name) {
        return doors.computeIfAbsent(name, n -> new RemoteDoor(link(), n, requester, doorSeconds));
    }

    /** @throws RuntimeException (with the reason) when the broker cannot be reached for the devices */
    RemoteLift lift(String name) {
        return lifts.computeIfAbsent(name, n -> new RemoteLift(link(), n, requester, liftSeconds));
    }

    /** Reports a device problem that did not fail the action (e.g. a door left open behind the robot). */
    void problem(String line) {
        problems.accept(line);
    }

    private synchronized DeviceLink link() {
        if (closed) {
            throw new IllegalStateException("the robot's use of the building's devices is closed");
        }
        if (link == null) {
            link = DeviceLink.over(master.link(), problems);
        }
        return link;
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (link != null) {
            link.close();
            link = null;
        }
    }
}
