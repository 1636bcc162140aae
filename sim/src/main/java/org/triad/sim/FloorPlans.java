package org.triad.sim;

import java.util.List;

/** Ready-made floor plans for examples, tests and benchmarks. */
public final class FloorPlans {
    private FloorPlans() {
    }

    /**
     * The default plan: {@code corridorWithRooms(List.of("storage", "room1", "room2", "room3"),
     * List.of("room4", "room5", "room6"), 6, 5, 2.4)}, with items {@code item1..item3} in {@code storage} within 0.8 m of its centre waypoint.
     * A 24 m x 2.4 m corridor; south rooms storage, room1, room2, room3 (connected to their neighbours by
     * internal doors, so e.g. storage to room2 has a route through the corridor and one through room1);
     * north rooms room4, room5, room6.
     */
    public static FloorPlan corridorWithRooms() {
        FloorPlan.Builder b = builder(List.of("storage", "room1", "room2", "room3"), List.of("room4", "room5", "room6"),
                6, 5, 2.4);
        return b.item("item1", 2.4, 2.0).item("item2", 3.6, 2.0).item("item3", 3.0, 1.8).build();
    }

    /**
     * A horizontal corridor with rooms on both sides. Room {@code i} of a side spans
     * {@code [i*roomWidth, (i+1)*roomWidth]}; south rooms lie below the corridor, north rooms above.
     * Doors and waypoints:
     * <ul>
     *   <li>door {@code <room>Door} (1.2 m) in the room's corridor wall (middle for south rooms, at 70% for north
     *       rooms so that no straight line passes two corridor doors);</li>
     *   <li>door {@code <a>-<b>} in the middle of the wall between neighbouring south rooms;</li>
     *   <li>waypoint {@code <room>} at each room centre, one per door at the door centre (door name),
     *       {@code <room>Front} in the corridor in front of each room door, {@code corridorWest} and
     *       {@code corridorEast} at the corridor ends;</li>
     *   <li>edges between all waypoint pairs in line of sight with 0.4 m clearance.</li>
     * </ul>
     *
     * @param roomWidth     metres along the corridor, &gt;= 3
     * @param roomDepth     metres across, &gt;= 3
     * @param corridorWidth metres, &gt;= 1.5
     * @throws IllegalArgumentException on empty room lists, duplicate names or too small dimensions
     */
    public static FloorPlan corridorWithRooms(List<String> south, List<String> north, double roomWidth,
                                              double roomDepth, double corridorWidth) {
        return builder(south, north, roomWidth, roomDepth, corridorWidth).build();
    }

    private static FloorPlan.Builder builder(List<String> south, List<String> north, double roomWidth, double roomDepth,
                                             double corridorWidth) {
        Checks.notNull("south rooms", south);
        Checks.notNull("north rooms", north);
        if (south.isEmpty() && north.isEmpty()) {
            throw new IllegalArgumentException("need at least one room");
        }
        atLeast("room width (m)", roomWidth, 3);
        atLeast("room depth (m)", roomDepth, 3);
        atLeast("corridor width (m)", corridorWidth, 1.5);
        double length = Math.max(south.size(), north.size()) * roomWidth;
        double y0 = roomDepth;
        double y1 = roomDepth + corridorWidth;
        double mid = (y0 + y1) / 2;
        FloorPlan.Builder b = FloorPlan.builder().corridor("corridor", 0, y0, length, y1);
        b.waypoint("corridorWest", 0.6, mid).waypoint("corridorEast", length - 0.6, mid);
        for (int i = 0; i < south.size(); i++) {
            String room = south.get(i);
            double x = (i + 0.5) * roomWidth;
            b.room(room, i * roomWidth, 0, (i + 1) * roomWidth, y0).door(room + "Door", room, "corridor", x, y0)
                    .waypoint(room + "Front", x, mid);
            if (i > 0) {
                String prev = south.get(i - 1);
                b.door(prev + "-" + room, prev, room, i * roomWidth, y0 / 2);
            }
        }
        for (int i = 0; i < north.size(); i++) {
            String room = north.get(i);
            double x = (i + 0.7) * roomWidth;
            b.room(room, i * roomWidth, y1, (i + 1) * roomWidth, y1 + roomDepth)
                    .door(room + "Door", room, "corridor", x, y1).waypoint(room + "Front", x, mid);
        }
        return b.roomWaypoints().doorWaypoints().lineOfSightEdges(0.4);
    }

    private static void atLeast(String what, double v, double min) {
        Checks.finite(what, v);
        if (v < min) {
            throw new IllegalArgumentException(what + " must be >= " + min + ", got " + v);
        }
    }
}
