package org.triad.examples.hospital.fleet;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.ToDoubleFunction;

import org.triad.examples.hospital.HospitalFloor;
import org.triad.examples.hospital.vda5050.SimulatedAgv;
import org.triad.refarc.fleet.FloorMap;

/**
 * The hospital's map cut into one map per floor, by the map ids its couriers report ({@link SimulatedAgv#mapId(int)}):
 * the simulation keeps both floors side by side in one plane ({@link HospitalFloor#floorAt}), an operator wants each
 * floor on its own.
 */
final class HospitalMaps {
    private HospitalMaps() {
    }

    /** Floor 0's and floor 1's maps, in that order, each with the rooms, walls, doors, waypoints, robots, items and people on it. */
    static Map<String, FloorMap> perFloor(FloorMap whole) {
        Map<String, FloorMap> floors = new LinkedHashMap<>();
        for (int floor = 0; floor <= 1; floor++) {
            List<FloorMap.Area> areas = on(whole.areas(), floor, a -> (a.box().minX() + a.box().maxX()) / 2);
            List<FloorMap.Line> walls = on(whole.walls(), floor, l -> (l.x1() + l.x2()) / 2);
            List<FloorMap.Door> doors = on(whole.doors(), floor, d -> (d.leaf().x1() + d.leaf().x2()) / 2);
            double minX = Double.POSITIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY;
            double maxX = Double.NEGATIVE_INFINITY;
            double maxY = Double.NEGATIVE_INFINITY;
            for (FloorMap.Area a : areas) {
                minX = Math.min(minX, a.box().minX());
                minY = Math.min(minY, a.box().minY());
                maxX = Math.max(maxX, a.box().maxX());
                maxY = Math.max(maxY, a.box().maxY());
            }
            FloorMap.Box bounds = areas.isEmpty() ? whole.bounds() : new FloorMap.Box(minX - 1, minY - 1, maxX + 1, maxY + 1);
            floors.put(SimulatedAgv.mapId(floor), new FloorMap(whole.time(), bounds, areas, walls, doors, on(whole.waypoints(), floor, FloorMap.Mark::x),
                    on(whole.robots(), floor, FloorMap.Mark::x), on(whole.items(), floor, FloorMap.Mark::x), on(whole.people(), floor, FloorMap.Mark::x)));
        }
        return floors;
    }

    private static <T> List<T> on(List<T> all, int floor, ToDoubleFunction<T> x) {
        List<T> mine = new ArrayList<>();
        for (T t : all) {
            if (HospitalFloor.floorAt(x.applyAsDouble(t)) == floor) {
                mine.add(t);
            }
        }
        return mine;
    }
}
