package org.triad.sim;

import java.util.ArrayList;
import java.util.List;

/**
 * Follows a polyline (start position, then waypoints): heads for the current target point, cuts
 * corners within a tolerance, slows for sharp turns, and brakes so it stops at the last point.
 */
final class PathFollower {
    private static final double CORNER_TOLERANCE = 0.3;
    private final List<Vec2> points;
    private final List<String> segmentDoors;
    private final double arrivalTolerance;
    private int target = 1;

    PathFollower(FloorPlan plan, Vec2 start, List<Vec2> via, double arrivalTolerance) {
        this.points = new ArrayList<>();
        points.add(start);
        points.addAll(via);
        this.arrivalTolerance = arrivalTolerance;
        this.segmentDoors = new ArrayList<>();
        for (int i = 0; i + 1 < points.size(); i++) {
            segmentDoors.add(plan.doorCrossed(points.get(i), points.get(i + 1)).map(Doorway::name).orElse(null));
        }
    }

    List<Vec2> points() {
        return points;
    }

    private int last() {
        return points.size() - 1;
    }

    private void advance(Vec2 pos) {
        while (target < last() && pos.distance(points.get(target)) < CORNER_TOLERANCE) {
            target++;
        }
    }

    boolean arrived(Vec2 pos) {
        advance(pos);
        return target == last() && pos.distance(points.get(last())) < arrivalTolerance;
    }

    /** Path length still to go, metres. */
    double remaining(Vec2 pos) {
        advance(pos);
        double r = pos.distance(points.get(target));
        for (int i = target; i < last(); i++) {
            r += points.get(i).distance(points.get(i + 1));
        }
        return r;
    }

    Vec2 desiredVelocity(Vec2 pos, double maxSpeed, double maxAcceleration) {
        advance(pos);
        Vec2 tgt = points.get(target);
        double dTarget = pos.distance(tgt);
        double rem = remaining(pos);
        double v = Math.min(maxSpeed, Math.sqrt(2 * 0.9 * maxAcceleration * Math.max(0, rem - 0.01)));
        if (target < last()) {
            Vec2 in = tgt.minus(pos).normalized();
            Vec2 out = points.get(target + 1).minus(tgt).normalized();
            double cornerSpeed = maxSpeed * Math.max(0.3, (1 + in.dot(out)) / 2);
            double dCorner = Math.max(0, dTarget - CORNER_TOLERANCE);
            v = Math.min(v, Math.sqrt(cornerSpeed * cornerSpeed + 2 * 0.9 * maxAcceleration * dCorner));
        }
        return tgt.minus(pos).normalized().times(v);
    }

    /** The closed door on the path within {@code range} metres ahead, or null. */
    Door closedDoorAhead(Vec2 pos, double range, Simulation sim) {
        advance(pos);
        double travelled = 0;
        Vec2 from = pos;
        for (int seg = target - 1; seg < last() && travelled <= range; seg++) {
            String door = segmentDoors.get(seg);
            if (door != null) {
                Door d = sim.door(door);
                double toDoor = travelled + from.distance(d.doorway().center());
                boolean ahead = seg != target - 1
                        || Segments.intersect(pos, points.get(target), d.doorway().end1(), d.doorway().end2());
                if (!d.isOpen() && ahead && toDoor <= range) {
                    return d;
                }
            }
            travelled += from.distance(points.get(seg + 1));
            from = points.get(seg + 1);
        }
        return null;
    }
}
