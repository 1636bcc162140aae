package org.triad.examples.hospital;

import java.util.LinkedHashMap;
import java.util.Map;

import org.triad.sim.Vec2;

/**
 * Where the robot and the people are, in model waypoints. A position alone is ambiguous near a door
 * (a person guided to c4 may still stand in the lobby's doorway), so the waypoint an action brought
 * someone to stays theirs while they remain within {@link HospitalFloor#AT_TOLERANCE} of it.
 */
final class Whereabouts {
    private final HospitalFloor floor;
    private final Map<String, String> arrivedAt = new LinkedHashMap<>();

    Whereabouts(HospitalFloor floor) {
        this.floor = floor;
    }

    /** An action brought {@code agent} to {@code waypoint}. */
    void arrived(String agent, String waypoint) {
        arrivedAt.put(agent, waypoint);
    }

    String of(String agent, Vec2 position) {
        return floor.waypointAt(position, arrivedAt.get(agent));
    }
}
