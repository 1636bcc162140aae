package org.triad.building.traffic;

import org.triad.building.traffic.Resource.Kind;

/** The floor maps of the traffic tests. */
final class Maps {
    private Maps() {
    }

    /**
     * Two halls joined by a corridor wide enough for one robot, and a side room off each hall:
     * {@code side-w - hall-w - c1 - c2 - hall-e - side-e}, corridor 'west' over c1, c2 and its three lanes.
     */
    static TrafficMap singleLane(int hallCapacity) {
        return TrafficMap.builder().node("side-w").node("hall-w", hallCapacity).node("c1").node("c2").node("hall-e", hallCapacity).node("side-e")
                .edge("side-w", "hall-w").edge("hall-w", "c1").edge("c1", "c2").edge("c2", "hall-e").edge("hall-e", "side-e")
                .area(Kind.CORRIDOR, "west", 1, "c1", "c2", "hall-w-c1", "c1-c2", "c2-hall-e").build();
    }

    /** Three halls in a ring of three single-lane corridors, each with a node in its middle: n1 - m12 - n2 - m23 - n3 - m31 - n1. */
    static TrafficMap ring(int hallCapacity) {
        TrafficMap.Builder b = TrafficMap.builder().node("n1", hallCapacity).node("n2", hallCapacity).node("n3", hallCapacity);
        String[][] legs = { { "n1", "m12", "n2" }, { "n2", "m23", "n3" }, { "n3", "m31", "n1" } };
        for (String[] l : legs) {
            b.node(l[1]).edge(l[0], l[1]).edge(l[1], l[2]).area(Kind.CORRIDOR, "corridor-" + l[1], 1, l[1], l[0] + "-" + l[1], l[1] + "-" + l[2]);
        }
        return b.build();
    }

    /** A hall on each floor and a lift for one robot between them: f1 - lift-1 = lift-2 - f2, the lift over both doors and the ride. */
    static TrafficMap lift() {
        return TrafficMap.builder().node("f1", 3).node("lift-1").node("lift-2").node("f2", 3)
                .edge("f1", "lift-1").edge("ride", "lift-1", "lift-2", 1).edge("lift-2", "f2")
                .area(Kind.LIFT, "lift", 1, "lift-1", "lift-2", "f1-lift-1", "ride", "lift-2-f2").build();
    }
}
