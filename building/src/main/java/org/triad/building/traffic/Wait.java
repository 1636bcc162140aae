package org.triad.building.traffic;

import java.util.List;

/**
 * A robot waiting for a stretch: since when (seconds on the table's clock), for which resources, held by
 * (or promised first to) which robots.
 *
 * @param stretch  the nodes it asked for, from its decision point on
 * @param blocking the resources it cannot have yet
 * @param blockers the robots holding them or queued for them ahead of it
 */
public record Wait(String robot, List<String> stretch, double since, List<Resource> blocking, List<String> blockers) {
    public Wait {
        stretch = List.copyOf(stretch);
        blocking = List.copyOf(blocking);
        blockers = List.copyOf(blockers);
    }

    /** Seconds waited by {@code now}. */
    public double waited(double now) {
        return now - since;
    }

    /** {@code courier-2 waits for corridor 'west' (held by courier-1)}: the operator's words. */
    public String reason() {
        return robot + " waits at " + stretch.get(0) + " for " + (blocking.isEmpty() ? "its turn" : join(blocking))
                + (blockers.isEmpty() ? "" : " (held by or promised to " + String.join(", ", blockers) + ")");
    }

    private static String join(List<Resource> rs) {
        return String.join(", ", rs.stream().map(Resource::toString).toList());
    }
}
