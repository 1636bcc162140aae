package org.triad.refarc.fleet;

import java.util.List;

/**
 * A picture of a floor at one moment, in metres (x to the right, y up), for an operator's map: what
 * the simulation's pictures draw, as plain data a web page can render.
 *
 * @param time seconds on the platform's clock when the picture was taken
 */
public record FloorMap(double time, Box bounds, List<Area> areas, List<Line> walls, List<Door> doors, List<Mark> waypoints,
        List<Mark> robots, List<Mark> items, List<Mark> people) {

    public FloorMap {
        areas = List.copyOf(areas);
        walls = List.copyOf(walls);
        doors = List.copyOf(doors);
        waypoints = List.copyOf(waypoints);
        robots = List.copyOf(robots);
        items = List.copyOf(items);
        people = List.copyOf(people);
    }

    public record Box(double minX, double minY, double maxX, double maxY) {
    }

    /** A room or corridor. */
    public record Area(String name, Box box, boolean corridor) {
    }

    public record Line(double x1, double y1, double x2, double y2) {
    }

    public record Door(String name, Line leaf, boolean open) {
    }

    /** Something at a point: a robot, item, person or waypoint; {@code note} e.g. what a robot carries. */
    public record Mark(String name, double x, double y, String note) {
    }
}
