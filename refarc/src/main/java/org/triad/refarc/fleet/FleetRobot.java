package org.triad.refarc.fleet;

import java.util.Optional;

import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;

/**
 * One robot of a fleet: what its own RefArc needs (state and actions) and, if the platform can tell,
 * a picture of where it is for the operator. Implementations are used by one RefArc at a time, but
 * {@link #floor()} is called from other threads.
 */
public interface FleetRobot extends AutoCloseable {
    /** Unique within the fleet; shown to people and used in URLs (letters, digits, '-', '_'). */
    String name();

    StateSource stateSource();

    ActionRunner actionRunner();

    /** The latest floor map around this robot (robots, items, people, doors), if the platform has one. */
    default Optional<FloorMap> floor() {
        return Optional.empty();
    }

    /**
     * The building's layout one map per floor, keyed by the map id a robot's {@link Pose#mapId()} names there, for a
     * building of several floors; empty (the default) when {@link #floor()} is the one map. Called from other threads.
     */
    default java.util.Map<String, FloorMap> floors() {
        return java.util.Map.of();
    }

    /** Where the robot is now, if its platform reports it: for the building's map. Called from other threads. */
    default Optional<Pose> pose() {
        return Optional.empty();
    }

    /** The robot's battery now, if its platform reports it: for the operator and the charging policy. Called from other threads. */
    default Optional<Battery> battery() {
        return Optional.empty();
    }

    /**
     * Whether this robot's platform observes the whole building (a simulation hosting every robot of the fleet):
     * then the world part of the state it reports is the building's world as it is, and the fleet's world follows
     * it instead of only what changed while the robot acted. Called once, when the robot joins.
     */
    default boolean observesBuilding() {
        return false;
    }

    /**
     * Called when the robot's task ended, before it takes another, on a thread of its own (blocking): a robot that stands
     * where the others must pass (a corridor junction) drives off to a place out of their way. Says where it went or why
     * it could not; empty when it stays where it is (the default).
     */
    default Optional<String> parkOutOfTheWay() {
        return Optional.empty();
    }

    /** Releases the connection or simulation; the default does nothing. */
    @Override
    default void close() {
    }
}
