package org.triad.sim;

import java.util.function.Consumer;

/**
 * Schedules events at one virtual time (seconds since start), obtained from {@link Simulation#at(double)}.
 * Events due at the same time run in scheduling order, before the agents act in that step.
 * Names are checked immediately; a bad name throws {@link IllegalArgumentException} here, not later.
 */
public final class EventScript {
    private final Simulation sim;
    private final double time;

    EventScript(Simulation sim, double time) {
        this.sim = sim;
        this.time = time;
    }

    /** Continues the script at another virtual time, seconds: {@code sim.at(5).closeDoor("d").at(9).openDoor("d")}. */
    public EventScript at(double t) {
        return sim.at(t);
    }

    /** Requests the door to close (it closes once nobody stands in the doorway). */
    public EventScript closeDoor(String door) {
        sim.door(door);
        sim.schedule(time, "close door " + door, () -> sim.closeDoor(door));
        return this;
    }

    public EventScript openDoor(String door) {
        sim.door(door);
        sim.schedule(time, "open door " + door, () -> sim.openDoor(door));
        return this;
    }

    /** Locks the door: the robot cannot open it. Does not close it. */
    public EventScript lockDoor(String door) {
        sim.door(door);
        sim.schedule(time, "lock door " + door, () -> sim.lockDoor(door, true));
        return this;
    }

    public EventScript unlockDoor(String door) {
        sim.door(door);
        sim.schedule(time, "unlock door " + door, () -> sim.lockDoor(door, false));
        return this;
    }

    /** A lift fault: the lift stops between floors on its current or next ride (see {@link Simulation#breakLift}). */
    public EventScript breakLift(String lift) {
        sim.lift(lift);
        sim.schedule(time, "break lift " + lift, () -> sim.breakLift(lift));
        return this;
    }

    /** Removes the item from the world (also from a robot carrying it). */
    public EventScript removeItem(String item) {
        sim.item(item);
        sim.schedule(time, "remove item " + item, () -> sim.removeItem(item));
        return this;
    }

    /**
     * Makes {@code people} persons stand in a row across the room or corridor at the middle of the segment
     * between two waypoints, for {@code seconds} of virtual time; then they leave. They are named
     * {@code blocker<k>.<i>} (k counts blockings from 1) and do not step aside for robots.
     *
     * @throws IllegalArgumentException for unknown waypoints, people &lt; 1 or a non-positive duration
     */
    public EventScript blockSegment(String waypointA, String waypointB, int people, double seconds) {
        Vec2 a = sim.plan().waypoint(waypointA).position();
        Vec2 b = sim.plan().waypoint(waypointB).position();
        if (people < 1) {
            throw new IllegalArgumentException("blocking needs at least one person, got " + people);
        }
        Checks.positive("blocking duration (s)", seconds);
        if (a.distance(b) < 1e-6) {
            throw new IllegalArgumentException("waypoints '" + waypointA + "' and '" + waypointB + "' coincide");
        }
        if (sim.plan().roomAt(a.plus(b).times(0.5)).isEmpty()) {
            throw new IllegalArgumentException("the middle of " + waypointA + "-" + waypointB + " is outside every room");
        }
        sim.schedule(time, "block " + waypointA + "-" + waypointB,
                () -> sim.blockSegment(a, b, people, time + seconds, waypointA + "-" + waypointB));
        return this;
    }

    /** Runs arbitrary code against the simulation (it must not call blocking robot activities). */
    public EventScript run(String label, Consumer<Simulation> action) {
        Checks.name("event label", label);
        Checks.notNull("action", action);
        sim.schedule(time, label, () -> action.accept(sim));
        return this;
    }
}
