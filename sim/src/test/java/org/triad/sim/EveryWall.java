package org.triad.sim;

/** The wall tests as they were before {@link WallGrid}: every wall of the plan, the reference the grid is held to. */
final class EveryWall {
    private EveryWall() {
    }

    static boolean isClear(FloorPlan plan, Vec2 a, Vec2 b, double clearance) {
        return plan.roomAt(a).isPresent() && plan.roomAt(b).isPresent() && plan.roomAt(a.plus(b).times(0.5)).isPresent()
                && plan.walls().stream().allMatch(w -> Segments.segmentDistance(a, b, w.a(), w.b()) >= clearance + plan.wallThickness() / 2);
    }

    static boolean clearOfWalls(FloorPlan plan, Vec2 p, double clearance) {
        return plan.wallClearance(p) >= clearance;
    }
}
