package org.triad.sim;

import java.util.Optional;

/** A small object that a robot can pick and place; it has no physical body. */
public final class Item {
    private final Simulation sim;
    private final String name;
    private Vec2 position;
    private Robot holder;
    private boolean removed;

    Item(Simulation sim, String name, Vec2 position) {
        this.sim = sim;
        this.name = name;
        this.position = position;
    }

    public String name() {
        return name;
    }

    /** Current position, metres (the carrier's position while carried). */
    public Vec2 position() {
        return holder != null ? holder.position() : position;
    }

    /** The robot carrying it, if any. */
    public Optional<Robot> holder() {
        return Optional.ofNullable(holder);
    }

    /** Whether a scripted event removed it from the world. */
    public boolean isRemoved() {
        return removed;
    }

    /** The room it is in, if any (empty when removed). */
    public Optional<Room> room() {
        return removed ? Optional.empty() : sim.plan().roomAt(position());
    }

    /** The waypoint nearest to it. */
    public Waypoint nearestWaypoint() {
        return sim.plan().nearestWaypoint(position());
    }

    void pickedBy(Robot r) {
        holder = r;
    }

    void placeAt(Vec2 p) {
        holder = null;
        position = p;
    }

    void remove() {
        if (holder != null) {
            position = holder.position();
            holder.dropSilently(this);
            holder = null;
        }
        removed = true;
    }
}
