package org.triad.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;

class FloorPlanTest {

    @Test
    void wallsLeaveGapsAtDoorsAndOpenings() {
        FloorPlan plan = FloorPlan.builder()
                .room("a", 0, 0, 4, 4).room("b", 4, 0, 8, 4).corridor("c", 0, 4, 8, 6).corridor("c2", 8, 4, 10, 6)
                .door("ab", "a", "b", 4, 2).door("ac", "a", "c", 2, 4).opening("c", "c2")
                .waypoint("wa", 2, 2).waypoint("wb", 6, 2).waypoint("wc", 2, 5).waypoint("wc2", 9, 5)
                .lineOfSightEdges(0.3).build();
        for (Wall w : plan.walls()) {
            for (Doorway d : plan.doorways()) {
                assertFalse(Segments.pointDistance(d.center(), w.a(), w.b()) < 0.5, "wall " + w + " covers door " + d.name());
            }
            assertFalse(Segments.intersect(w.a(), w.b(), new Vec2(8, 4.5), new Vec2(8, 5.5)), "opening walled: " + w);
        }
        assertEquals("ab", plan.edge("wa", "wb").orElseThrow().door());
        assertEquals("ac", plan.edge("wa", "wc").orElseThrow().door());
        assertNull(plan.edge("wc", "wc2").orElseThrow().door());
        assertTrue(plan.edge("wb", "wc").isEmpty(), "b has no door to c");
        assertEquals("b", plan.roomAt(new Vec2(6, 1)).orElseThrow().name());
        assertEquals("wb", plan.nearestWaypoint(new Vec2(7, 1)).name());
    }

    @Test
    void readmeExampleBuildsAndRoutesAroundAClosedDoor() {
        FloorPlan plan = FloorPlan.builder()
                .corridor("hall", 0, 5, 24, 7.4)
                .room("storage", 0, 0, 6, 5).door("storageDoor", "storage", "hall", 3, 5)
                .room("ward", 6, 0, 12, 5).door("wardDoor", "ward", "hall", 9, 5)
                .door("storage-ward", "storage", "ward", 6, 2.5)
                .waypoint("hallWest", 0.6, 6.2).waypoint("hallStorage", 3, 6.2).waypoint("hallWard", 9, 6.2)
                .roomWaypoints()
                .doorWaypoints()
                .lineOfSightEdges(0.4)
                .item("box", 3, 2)
                .build();
        Simulation sim = Simulation.builder(plan).build();
        Robot robot = sim.addRobot("robot", "storage", RobotSpec.defaults());
        sim.closeDoor("storage-ward");
        assertTrue(robot.pick("box").success());
        ActionResult move = robot.moveTo("ward");
        assertTrue(move.success() && move.action().contains("hallWard"), "the robot sees the closed door 3 m away"
                + " and takes the hall: " + move);
        assertTrue(robot.place("box").success());
        assertEquals("ward", sim.item("box").room().orElseThrow().name());
    }

    @Test
    void exampleCorridorPlanIsConnectedAndHasAlternativeRoutes() {
        FloorPlan plan = FloorPlans.corridorWithRooms();
        Set<String> reached = new TreeSet<>();
        Deque<String> todo = new ArrayDeque<>();
        todo.add("storage");
        while (!todo.isEmpty()) {
            String w = todo.poll();
            if (reached.add(w)) {
                plan.edgesOf(w).forEach(e -> todo.add(e.other(w)));
            }
        }
        assertEquals(plan.waypoints().size(), reached.size(), "every waypoint reachable from storage");
        for (GraphEdge e : plan.edges()) {
            assertTrue(plan.isClear(plan.waypoint(e.from()).position(), plan.waypoint(e.to()).position(), 0.4), e::toString);
        }
        PathPlanner planner = new PathPlanner(plan);
        Vec2 storage = plan.waypoint("storage").position();
        var direct = planner.route(storage, "room2", Set.of(), 0.3).orElseThrow();
        var detour = planner.route(storage, "room2", Set.of("room1-room2"), 0.3).orElseThrow();
        assertTrue(direct.contains("room1"), direct::toString);
        assertTrue(detour.contains("room2Front"), detour::toString);
        assertTrue(planner.route(storage, "room2", Set.of("room1-room2", "room2Door"), 0.3).orElseThrow()
                .contains("room3"), "third route via room3");
        assertEquals(3, plan.items().size());
        plan.items().forEach(i -> assertEquals("storage", plan.roomAt(i.position()).orElseThrow().name()));
    }

    /** The wall grid answers as testing every wall does: segments and points all over a plan, some on walls and corners. */
    @Test
    void theWallGridAnswersAsEveryWallDoes() {
        FloorPlan plan = FloorPlans.corridorWithRooms(java.util.List.of("s1", "s2", "s3", "s4", "s5", "s6"),
                java.util.List.of("n1", "n2", "n3", "n4", "n5"), 6, 5, 2.4);
        java.util.SplittableRandom random = new java.util.SplittableRandom(7);
        Rect b = plan.bounds();
        int clear = 0;
        int free = 0;
        for (int i = 0; i < 4_000; i++) {
            Vec2 p = point(plan, random, b);
            Vec2 q = random.nextInt(4) == 0 ? p.plus(new Vec2(random.nextDouble(-1, 1), random.nextDouble(-1, 1))) : point(plan, random, b);
            double clearance = random.nextInt(5) == 0 ? 0 : random.nextDouble(0, 1.5);
            boolean byEveryWall = EveryWall.isClear(plan, p, q, clearance);
            assertEquals(byEveryWall, plan.isClear(p, q, clearance), p + " -> " + q + " at " + clearance);
            assertEquals(EveryWall.clearOfWalls(plan, p, clearance), plan.clearOfWalls(p, clearance), p + " at " + clearance);
            clear += byEveryWall ? 1 : 0;
            free += plan.clearOfWalls(p, clearance) ? 1 : 0;
        }
        assertTrue(clear > 200 && clear < 3_800 && free > 200 && free < 3_800, "both answers are tested often: " + clear + ", " + free);
    }

    /** A point of the plan's bounds (a little beyond them too), a fifth of them on a wall's end or middle. */
    private static Vec2 point(FloorPlan plan, java.util.SplittableRandom random, Rect b) {
        if (random.nextInt(5) == 0) {
            Wall w = plan.walls().get(random.nextInt(plan.walls().size()));
            return random.nextBoolean() ? w.a() : w.a().plus(w.b()).times(0.5);
        }
        return new Vec2(random.nextDouble(b.minX() - 1, b.maxX() + 1), random.nextDouble(b.minY() - 1, b.maxY() + 1));
    }
}
