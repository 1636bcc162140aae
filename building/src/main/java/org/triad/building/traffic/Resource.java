package org.triad.building.traffic;

import java.util.Objects;

/**
 * Something only so many robots may occupy at once: a node (a spot on the floor), an edge (the lane between
 * two nodes) or an area (a narrow corridor, a doorway, the lift cabin) covering several nodes and edges.
 *
 * @param kind     what it is, for reasons an operator reads ("waiting for lift 'lift-a'")
 * @param id       unique among the resources of its kind
 * @param capacity how many robots it holds at once, at least 1
 */
public record Resource(Kind kind, String id, int capacity) {
    /** What a resource is. Areas come in kinds so that waiting times can be told apart (doors, the lift, corridors). */
    public enum Kind {
        NODE, EDGE, CORRIDOR, DOOR, LIFT, ZONE;

        boolean isArea() {
            return this != NODE && this != EDGE;
        }

        String label() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    public Resource {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(id, "id");
    }

    /** {@code corridor 'west'}, {@code node 'c4'}. */
    @Override
    public String toString() {
        return kind.label() + " '" + id + "'";
    }
}
