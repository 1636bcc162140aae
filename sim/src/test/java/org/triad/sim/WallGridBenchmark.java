package org.triad.sim;

import java.util.List;
import java.util.SplittableRandom;

/**
 * A main, not a test: what a robot's wall tests of one step cost with the {@link WallGrid} and with every wall (the
 * code before it), in one run, so that both figures see the same machine load. The queries are the step's: a line of
 * sight from the robot to a door centre within 3 m ({@code isClear} at clearance 0) and the steering's probe
 * ({@code clearOfWalls} at the robot's radius), from random points in the rooms of a plan with
 * {@code [rooms]} rooms a side (default 12: about the hospital's two floors' walls).
 * <pre>java -cp sim/target/classes:sim/target/test-classes org.triad.sim.WallGridBenchmark [rooms] [queries]</pre>
 */
public final class WallGridBenchmark {
    private WallGridBenchmark() {
    }

    public static void main(String[] args) {
        int rooms = args.length > 0 ? Integer.parseInt(args[0]) : 12;
        int queries = args.length > 1 ? Integer.parseInt(args[1]) : 200_000;
        List<String> south = java.util.stream.IntStream.range(0, rooms).mapToObj(i -> "s" + i).toList();
        List<String> north = java.util.stream.IntStream.range(0, rooms).mapToObj(i -> "n" + i).toList();
        FloorPlan plan = FloorPlans.corridorWithRooms(south, north, 6, 5, 2.4);
        Vec2[] from = new Vec2[queries];
        Vec2[] to = new Vec2[queries];
        SplittableRandom random = new SplittableRandom(1);
        List<Room> all = plan.rooms();
        for (int i = 0; i < queries; i++) {
            Rect r = all.get(random.nextInt(all.size())).bounds();
            from[i] = new Vec2(random.nextDouble(r.minX(), r.maxX()), random.nextDouble(r.minY(), r.maxY()));
            to[i] = from[i].plus(new Vec2(random.nextDouble(-2, 2), random.nextDouble(-2, 2)));
        }
        System.out.printf("plan: %d rooms, %d walls; %d queries of each kind, best of 5 rounds%n", all.size(), plan.walls().size(), queries);
        System.out.printf("%-32s %14s %14s%n", "", "isClear [ns]", "clearOfWalls [ns]");
        for (int round = 0; round < 2; round++) {
            // twice, so that the second pair of lines is after the JIT has compiled both
            double everyLine = best(() -> { int n = 0; for (int i = 0; i < queries; i++) { n += EveryWall.isClear(plan, from[i], to[i], 0) ? 1 : 0; } return n; });
            double everyPoint = best(() -> { int n = 0; for (int i = 0; i < queries; i++) { n += EveryWall.clearOfWalls(plan, from[i], 0.3) ? 1 : 0; } return n; });
            double gridLine = best(() -> { int n = 0; for (int i = 0; i < queries; i++) { n += plan.isClear(from[i], to[i], 0) ? 1 : 0; } return n; });
            double gridPoint = best(() -> { int n = 0; for (int i = 0; i < queries; i++) { n += plan.clearOfWalls(from[i], 0.3) ? 1 : 0; } return n; });
            if (round == 1) {
                System.out.printf("%-32s %14.0f %14.0f%n", "every wall (before)", everyLine / queries, everyPoint / queries);
                System.out.printf("%-32s %14.0f %14.0f%n", "wall grid (" + WallGrid.CELL + " m cells)", gridLine / queries, gridPoint / queries);
                System.out.printf("%-32s %13.1fx %13.1fx%n", "speed-up", everyLine / gridLine, everyPoint / gridPoint);
            }
        }
    }

    /** The least wall time of 5 runs of {@code work}, nanoseconds. */
    private static double best(java.util.function.IntSupplier work) {
        double best = Double.MAX_VALUE;
        int sink = 0;
        for (int i = 0; i < 5; i++) {
            long t0 = System.nanoTime();
            sink += work.getAsInt();
            best = Math.min(best, System.nanoTime() - t0);
        }
        if (sink < 0) {
            System.out.println(sink);
        }
        return best;
    }
}
