package org.triad.building;

import org.triad.building.traffic.TrafficBoard;
import org.triad.refarc.fleet.FleetContext;

/**
 * What a fleet service gives robot platform providers when the robots share one building: the
 * models' situations and the building's {@link SharedWorld}. Providers whose robots have no platform
 * of their own (e.g. {@code dry}) put them into this world; robots with a platform are observed by it.
 */
public interface BuildingContext extends FleetContext {
    SharedWorld world();

    /** Where a provider whose robots run under traffic control shows their waits to the operator (a fresh, unseen board by default). */
    default TrafficBoard traffic() {
        return new TrafficBoard();
    }

    /** Where a provider whose building has devices (doors, lifts) shows their states to the operator (a fresh, unseen board by default). */
    default DeviceBoard devices() {
        return new DeviceBoard();
    }
}
