package org.triad.sim;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * The walls of a floor plan bucketed in a uniform grid of square cells, so that a clearance test looks at the walls
 * near its segment or point instead of every wall of the building: each robot tests its clearance and line of sight
 * every step (vda5050/BENCHMARK.md, the profile of 20 couriers: {@code FloorPlan.isClear} was 13 % of the building's
 * samples). A wall is in every cell its bounding box touches; a query visits the cells its bounding box, widened by
 * the distance it asks about, touches. Any wall nearer than that distance to the query has a point in that widened
 * box, hence shares a cell with it, so the answers are those of testing every wall.
 */
final class WallGrid {
    /** Cell side, metres: about a corridor's width, so a step's query touches a few cells holding a few walls each. */
    static final double CELL = 2.0;
    /** Widens every query's box a little, so that rounding at a cell's border never leaves a near wall out. */
    private static final double MARGIN = 1e-6;

    private final List<Wall> walls;
    private final double originX;
    private final double originY;
    private final int columns;
    private final int rows;
    /** Per cell (row-major), the indices into {@link #walls} of the walls whose bounding box touches it. */
    private final int[][] cells;

    WallGrid(List<Wall> walls, Rect bounds) {
        this.walls = walls;
        this.originX = bounds.minX() - CELL;
        this.originY = bounds.minY() - CELL;
        this.columns = Math.max(1, (int) Math.ceil((bounds.maxX() - originX) / CELL) + 2);
        this.rows = Math.max(1, (int) Math.ceil((bounds.maxY() - originY) / CELL) + 2);
        List<List<Integer>> buckets = new ArrayList<>(columns * rows);
        for (int i = 0; i < columns * rows; i++) {
            buckets.add(new ArrayList<>(0));
        }
        for (int w = 0; w < walls.size(); w++) {
            Wall wall = walls.get(w);
            int c0 = column(Math.min(wall.a().x(), wall.b().x()));
            int c1 = column(Math.max(wall.a().x(), wall.b().x()));
            int r0 = row(Math.min(wall.a().y(), wall.b().y()));
            int r1 = row(Math.max(wall.a().y(), wall.b().y()));
            for (int r = r0; r <= r1; r++) {
                for (int c = c0; c <= c1; c++) {
                    buckets.get(r * columns + c).add(w);
                }
            }
        }
        this.cells = new int[buckets.size()][];
        for (int i = 0; i < cells.length; i++) {
            cells[i] = buckets.get(i).stream().mapToInt(Integer::intValue).toArray();
        }
    }

    /** Whether some wall's centre line is nearer than {@code distance} to the segment {@code a}-{@code b}. */
    boolean anyNearSegment(Vec2 a, Vec2 b, double distance) {
        BitSet seen = new BitSet(walls.size());
        double reach = distance + MARGIN;
        int c0 = column(Math.min(a.x(), b.x()) - reach);
        int c1 = column(Math.max(a.x(), b.x()) + reach);
        int r0 = row(Math.min(a.y(), b.y()) - reach);
        int r1 = row(Math.max(a.y(), b.y()) + reach);
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int w : cells[r * columns + c]) {
                    if (!seen.get(w)) {
                        seen.set(w);
                        Wall wall = walls.get(w);
                        if (Segments.segmentDistance(a, b, wall.a(), wall.b()) < distance) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    /** Whether some wall's surface, {@code halfThickness} off its centre line, is nearer than {@code clearance} to {@code p}. */
    boolean anyNearPoint(Vec2 p, double clearance, double halfThickness) {
        double reach = clearance + halfThickness + MARGIN;
        int c0 = column(p.x() - reach);
        int c1 = column(p.x() + reach);
        int r0 = row(p.y() - reach);
        int r1 = row(p.y() + reach);
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int w : cells[r * columns + c]) {
                    Wall wall = walls.get(w);
                    // the same expression as FloorPlan.wallClearance's, so that rounding decides alike
                    if (Segments.pointDistance(p, wall.a(), wall.b()) - halfThickness < clearance) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** The cell column of {@code x}, clamped to the grid (everything beyond the plan's bounds shares its border cells). */
    private int column(double x) {
        return Math.max(0, Math.min(columns - 1, (int) Math.floor((x - originX) / CELL)));
    }

    private int row(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - originY) / CELL)));
    }
}
