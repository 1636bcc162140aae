package org.triad.sim;

/** Why a robot activity failed. */
public enum Failure {
    /** A closed door on the route stayed closed for longer than the robot's door wait. */
    DOOR_CLOSED,
    /** The robot tried to open a locked door. */
    DOOR_LOCKED,
    /** The robot made no progress (people or other obstacles in the way) for longer than its blocked timeout. */
    PATH_BLOCKED,
    /** No route exists in the waypoint graph without doors known to be closed. */
    NO_ROUTE,
    /** The activity exceeded its overall time limit. */
    TIMEOUT,
    /** The item, door or person is farther away than the robot's reach. */
    OUT_OF_REACH,
    /** The item does not exist any more, or someone else holds it. */
    ITEM_UNAVAILABLE,
    /** The robot is not carrying the item it should place. */
    NOT_CARRYING,
    /** The robot already carries as many items as it can. */
    CAPACITY_EXCEEDED,
    /** The person to guide or follow fell too far behind or disappeared. */
    PERSON_LOST,
    /** The robot's battery is empty: it cannot drive (see {@link Battery}). */
    BATTERY_EMPTY
}
