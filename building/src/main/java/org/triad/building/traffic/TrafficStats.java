package org.triad.building.traffic;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.triad.building.traffic.Resource.Kind;

/**
 * What the reservation table observed: how long robots held each resource, and how long requests waited,
 * told apart by what they waited for (the lift, a door, a corridor, a node or lane). Seconds on the table's clock.
 */
public final class TrafficStats {
    /** The order in which a wait is put down to one kind: a wait for the lift and a corridor counts as the lift's. */
    private static final List<Kind> PRECEDENCE = List.of(Kind.LIFT, Kind.DOOR, Kind.CORRIDOR, Kind.ZONE, Kind.EDGE, Kind.NODE);

    private final Map<Resource, double[]> holds = new HashMap<>();
    private final Map<Kind, List<Double>> waits = new EnumMap<>(Kind.class);
    private final List<Double> allWaits = new ArrayList<>();
    private long grantsAfterWaiting;

    TrafficStats(TrafficMap map) {
        for (Kind k : Kind.values()) {
            waits.put(k, new ArrayList<>());
        }
    }

    void held(Resource r, double seconds) {
        double[] h = holds.computeIfAbsent(r, k -> new double[2]);
        h[0]++;
        h[1] += seconds;
    }

    void waited(Set<Resource> blocking, double seconds) {
        grantsAfterWaiting++;
        allWaits.add(seconds);
        for (Kind k : PRECEDENCE) {
            if (blocking.stream().anyMatch(r -> r.kind() == k)) {
                waits.get(k).add(seconds);
                return;
            }
        }
    }

    /** Mean seconds one robot held this resource, or 0 before anyone released it. */
    public double meanHold(Resource r) {
        double[] h = holds.get(r);
        return h == null ? 0 : h[1] / h[0];
    }

    /** The seconds each granted request waited (those granted at once not included), in order. */
    public List<Double> waits() {
        return Collections.unmodifiableList(allWaits);
    }

    /** The waits put down to this kind of resource (see the precedence: lift, door, corridor, zone, edge, node). */
    public List<Double> waits(Kind kind) {
        return Collections.unmodifiableList(waits.get(kind));
    }

    public long grantsAfterWaiting() {
        return grantsAfterWaiting;
    }

    /** The q-quantile (0..1, nearest rank) of these seconds, 0 for none. */
    public static double quantile(List<Double> xs, double q) {
        if (xs.isEmpty()) {
            return 0;
        }
        List<Double> s = new ArrayList<>(xs);
        Collections.sort(s);
        int i = (int) Math.ceil(q * s.size()) - 1;
        return s.get(Math.max(0, Math.min(s.size() - 1, i)));
    }
}
