package org.triad.sim;

/**
 * An undirected edge of the waypoint graph with its length in metres, and the name of the door it
 * passes through ({@code null} if none).
 */
public record GraphEdge(String from, String to, double length, String door) {

    /** The end that is not {@code name}. */
    public String other(String name) {
        return from.equals(name) ? to : from;
    }
}
