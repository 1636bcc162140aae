package org.triad.sim;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.PriorityQueue;
import java.util.Set;

/**
 * Shortest routes on the waypoint graph (Dijkstra from the goal, ties broken by declaration order),
 * entered from an arbitrary position through the best visible waypoint.
 */
final class PathPlanner {
    private final FloorPlan plan;
    private final List<Waypoint> nodes;
    private final Map<String, Integer> index = new HashMap<>();

    PathPlanner(FloorPlan plan) {
        this.plan = plan;
        this.nodes = plan.waypoints();
        for (int i = 0; i < nodes.size(); i++) {
            index.put(nodes.get(i).name(), i);
        }
    }

    /** Waypoint names from an entry waypoint to {@code goal}, avoiding edges through {@code closedDoors}. */
    Optional<List<String>> route(Vec2 from, String goal, Set<String> closedDoors, double clearance) {
        int g = index.get(plan.waypoint(goal).name());
        double[] dist = new double[nodes.size()];
        int[] next = new int[nodes.size()];
        Arrays.fill(dist, Double.POSITIVE_INFINITY);
        Arrays.fill(next, -1);
        dist[g] = 0;
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> a[0] != b[0] ? Double.compare(a[0], b[0])
                : Double.compare(a[1], b[1]));
        queue.add(new double[] {0, g});
        while (!queue.isEmpty()) {
            double[] top = queue.poll();
            int u = (int) top[1];
            if (top[0] > dist[u]) {
                continue;
            }
            for (GraphEdge e : plan.edgesOf(nodes.get(u).name())) {
                if (e.door() != null && closedDoors.contains(e.door())) {
                    continue;
                }
                int v = index.get(e.other(nodes.get(u).name()));
                double d = dist[u] + e.length();
                if (d < dist[v]) {
                    dist[v] = d;
                    next[v] = u;
                    queue.add(new double[] {d, v});
                }
            }
        }
        int entry = -1;
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < nodes.size(); i++) {
            if (Double.isInfinite(dist[i])) {
                continue;
            }
            Vec2 p = nodes.get(i).position();
            double cost = from.distance(p) + dist[i];
            if (cost < best && entryOk(from, p, closedDoors, clearance)) {
                best = cost;
                entry = i;
            }
        }
        if (entry < 0) {
            // squeezed against a wall or a jamb no waypoint is in clear sight: take the nearest one
            // that is at least not behind a wall, and let the contact physics slide the disc along
            for (int i = 0; i < nodes.size(); i++) {
                Vec2 p = nodes.get(i).position();
                if (!Double.isInfinite(dist[i]) && from.distance(p) + dist[i] < best
                        && entryOk(from, p, closedDoors, 0.01)) {
                    best = from.distance(p) + dist[i];
                    entry = i;
                }
            }
        }
        if (entry < 0) {
            return Optional.empty();
        }
        List<String> route = new ArrayList<>();
        for (int i = entry; i >= 0; i = next[i]) {
            route.add(nodes.get(i).name());
        }
        return Optional.of(Collections.unmodifiableList(route));
    }

    private boolean entryOk(Vec2 from, Vec2 p, Set<String> closedDoors, double clearance) {
        if (from.distance(p) < 0.05) {
            return true;
        }
        if (plan.doorsCrossed(from, p) > 1) {
            return false;
        }
        Optional<Doorway> door = plan.doorCrossed(from, p);
        if (door.isPresent() && closedDoors.contains(door.get().name())) {
            return false;
        }
        return plan.isClear(from, p, clearance);
    }
}
