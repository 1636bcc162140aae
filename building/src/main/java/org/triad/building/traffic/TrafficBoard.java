package org.triad.building.traffic;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Supplier;

import org.triad.runtime.schema.ActionCosts;

/**
 * What the operator sees of traffic: the robots waiting for a resource, for how long, for what and behind whom.
 * Each traffic control of the building (a master's, a simulation's) adds itself as a source; the service asks
 * for the waits longer than a bound. Thread-safe.
 */
public final class TrafficBoard {
    /**
     * One robot waiting.
     *
     * @param seconds   how long it has waited so far
     * @param reason    {@link Wait#reason()}: {@code courier-2 waits at hall-e for corridor 'west' (held by or promised to courier-1)}
     * @param resources the resources it cannot have yet
     * @param heldBy    the robots holding them or queued for them first
     */
    public record Waiting(String robot, double seconds, String reason, List<String> resources, List<String> heldBy) {
        public Waiting {
            resources = List.copyOf(resources);
            heldBy = List.copyOf(heldBy);
        }
    }

    private final List<Supplier<List<Waiting>>> sources = new CopyOnWriteArrayList<>();
    private final List<ActionCosts> costs = new CopyOnWriteArrayList<>();

    /** Adds a traffic control's waits (called at each look; it locks its own table). */
    public void add(Supplier<List<Waiting>> source) {
        sources.add(Objects.requireNonNull(source, "source"));
    }

    /**
     * Adds a traffic control's congestion costs ({@code TrafficControl.congestion}): the fleet's planner then
     * prices each move by its expected wait, so a robot may take the free side of the ring.
     */
    public void addCosts(ActionCosts source) {
        costs.add(Objects.requireNonNull(source, "source"));
    }

    /** The sum of every added source's costs, or empty while no traffic control added any (plans stay shortest). */
    public java.util.Optional<ActionCosts> costs() {
        if (costs.isEmpty()) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(action -> {
            double sum = 0;
            for (ActionCosts c : costs) {
                sum += c.extra(action);
            }
            return sum;
        });
    }

    /** Every robot that has waited longer than {@code boundSeconds}, the longest first. */
    public List<Waiting> longerThan(double boundSeconds) {
        if (!(boundSeconds >= 0) || Double.isInfinite(boundSeconds)) {
            throw new IllegalArgumentException("a wait bound is a number of seconds, at least 0, not " + boundSeconds);
        }
        List<Waiting> all = new ArrayList<>();
        for (Supplier<List<Waiting>> s : sources) {
            for (Waiting w : s.get()) {
                if (w.seconds() > boundSeconds) {
                    all.add(w);
                }
            }
        }
        all.sort(Comparator.comparingDouble(Waiting::seconds).reversed());
        return all;
    }

    /** The waits in this table now, for the board (call it under the table's owner's lock). */
    public static List<Waiting> waiting(ReservationTable table) {
        double now = table.now();
        return table.waits().stream().map(w -> new Waiting(w.robot(), w.waited(now), w.reason(),
                w.blocking().stream().map(Resource::toString).toList(), w.blockers())).toList();
    }
}
