package org.triad.building;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Supplier;

/**
 * What the operator sees of the building's devices (doors, lifts): each one's last reported state. Providers whose
 * robots share a building with devices add a source (e.g. master control watching the device protocol); the service
 * lists them under {@code /api/devices} and on the operator page. Thread-safe.
 */
public final class DeviceBoard {
    /**
     * One device as it last reported itself.
     *
     * @param kind   {@code door} or {@code lift}
     * @param state  a door's mode ({@code OPEN}, {@code CLOSED}, {@code MOVING}), a lift's motion ({@code STOPPED}, {@code MOVING}, {@code FAULT})
     * @param detail what else the state says (a lift's floor, destination and door), may be empty
     * @param reason why the device refused or stopped, or null
     * @param since  the device's timestamp of that state (ISO 8601), or null
     */
    public record Device(String kind, String name, String state, String detail, String reason, String since) {
        public Device {
            Objects.requireNonNull(kind, "kind");
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(state, "state");
            detail = detail == null ? "" : detail;
        }
    }

    private final List<Supplier<List<Device>>> sources = new CopyOnWriteArrayList<>();

    /** Adds a source of device states (called at each look). */
    public void add(Supplier<List<Device>> source) {
        sources.add(Objects.requireNonNull(source, "source"));
    }

    /** Every device of every source, by kind and name. */
    public List<Device> devices() {
        List<Device> all = new ArrayList<>();
        for (Supplier<List<Device>> s : sources) {
            all.addAll(s.get());
        }
        all.sort(Comparator.comparing(Device::kind).thenComparing(Device::name));
        return all;
    }
}
