package org.triad.building.traffic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;

import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Resource.Kind;

/**
 * Random buildings, random fleets, random errands, random faults: after every step no resource holds more
 * robots than its capacity, no wait-for cycle exists, and the fleet is never stuck with every robot waiting
 * and none able to move (a deadlock). Seeds make each run reproducible.
 */
class ReservationPropertyTest {

    @Test
    void noResourceOverfullNoWaitForCycleNoDeadlock() {
        int moved = 0;
        for (long seed = 1; seed <= 12; seed++) {
            moved += run(seed);
        }
        assertTrue(moved > 1500, "the fleets moved: " + moved + " nodes passed in all");
    }

    /** Runs one random building; returns the nodes its robots passed. */
    private int run(long seed) {
        Random rnd = new Random(seed);
        Random guides = new Random(~seed); // a request in eight guides a person, one in eight is urgent (rule 3's precedence case), apart from the errands' draws
        TrafficMap map = randomBuilding(rnd);
        double[] now = { 0 };
        ReservationTable t = new ReservationTable(map, () -> now[0]);
        List<String> stops = map.nodeIds().stream().filter(map::isStop).toList();
        int fleet = 2 + rnd.nextInt(9);
        List<String> robots = new ArrayList<>();
        Map<String, Deque<String>> routes = new HashMap<>();
        List<String> free = new ArrayList<>(stops);
        Collections.shuffle(free, rnd);
        for (int i = 0; i < fleet && i < free.size(); i++) {
            String r = "r" + i;
            t.place(r, free.get(i));
            robots.add(r);
            routes.put(r, new LinkedList<>());
        }
        Set<String> lost = new HashSet<>();
        int passedNodes = 0;
        int errandsDone = 0;
        for (int step = 0; step < 2000; step++) {
            now[0] += rnd.nextDouble();
            String r = robots.get(rnd.nextInt(robots.size()));
            if (lost.contains(r)) {
                if (rnd.nextInt(50) == 0) { // taken away and brought back at a free stop node
                    t.remove(r);
                    lost.remove(r);
                    String at = stops.get(rnd.nextInt(stops.size()));
                    try {
                        t.place(r, at);
                    } catch (IllegalStateException full) { // no room there after the robots waiting for it
                        robots.remove(r);
                    }
                }
                continue;
            }
            List<String> base = t.base(r);
            if (base.size() > 1) {
                t.passed(r, base.get(1));
                passedNodes++;
                if (t.base(r).size() == 1 && routes.get(r).size() <= 1 && t.waiting(r).isEmpty()) {
                    errandsDone++;
                }
            } else if (t.waiting(r).isPresent()) {
                if (rnd.nextInt(40) == 0) {
                    t.cancel(r);
                    routes.get(r).clear();
                }
            } else {
                Deque<String> route = routes.get(r);
                if (route.size() <= 1 || !route.peekFirst().equals(t.decisionPoint(r))) {
                    route.clear();
                    route.addAll(shortestPath(map, t.decisionPoint(r), stops.get(rnd.nextInt(stops.size()))));
                }
                if (route.size() > 1) {
                    int kind = guides.nextInt(8); // a guide or an urgent robot (rule 3's precedence case) in four
                    Decision d = t.request(r, List.copyOf(route), kind == 0 ? Precedence.GUIDE : kind == 1 ? Precedence.URGENT : Precedence.PLAIN);
                    t.takeDisplaced(); // robots refused to let a guide (or a robot out of a dead end) through ask again later
                    if (d instanceof Granted g) {
                        route.clear();
                        route.addAll(g.horizon().isEmpty() ? List.of(g.decisionPoint()) : g.horizon());
                    } else if (d instanceof Refused) {
                        route.clear(); // re-plan: another errand next time
                    }
                }
            }
            if (rnd.nextInt(1500) == 0) {
                String victim = robots.get(rnd.nextInt(robots.size()));
                if (!lost.contains(victim)) {
                    t.lost(victim, "CONNECTIONBROKEN");
                    lost.add(victim);
                }
            }
            check(t, map, robots, lost, seed, step);
        }
        assertTrue(passedNodes > 0 && errandsDone > 0, "the fleet moved: " + passedNodes + " nodes passed, " + errandsDone + " errands done (seed " + seed + ")");
        return passedNodes;
    }

    private static void check(ReservationTable t, TrafficMap map, List<String> robots, Set<String> lost, long seed, int step) {
        Map<Resource, Integer> count = new HashMap<>();
        for (String r : robots) {
            if (!t.robots().contains(r)) {
                continue;
            }
            for (Resource x : t.holding(r)) {
                count.merge(x, 1, Integer::sum);
            }
            assertTrue(t.holding(r).containsAll(map.standing(t.base(r).get(0))), r + " holds where it stands");
        }
        count.forEach((x, n) -> {
            if (n > x.capacity()) {
                fail(x + " held by " + n + " robots, capacity " + x.capacity() + " (seed " + seed + ", step " + step + ")");
            }
        });
        assertEquals(Set.of(), Graphs.cycle(t.waitsFor()), "wait-for cycle (seed " + seed + ", step " + step + ")");
        List<String> live = robots.stream().filter(r -> t.robots().contains(r) && !lost.contains(r)).toList();
        boolean allWaiting = !live.isEmpty() && live.stream().allMatch(r -> t.waiting(r).isPresent());
        boolean noneCanMove = live.stream().allMatch(r -> t.base(r).size() == 1);
        assertFalse(allWaiting && noneCanMove, "deadlock: every robot waits and none can move " + t.waits() + " (seed " + seed + ", step " + step + ")");
    }

    /**
     * A grid of halls (capacity 1 or 2), neighbours joined by a direct lane or by a single-lane corridor of one
     * or two nodes, one vertical pair joined by a lift for one robot, some lanes through a door.
     */
    static TrafficMap randomBuilding(Random rnd) {
        int w = 3 + rnd.nextInt(3);
        int h = 2 + rnd.nextInt(3);
        TrafficMap.Builder b = TrafficMap.builder();
        for (int x = 0; x < w; x++) {
            for (int y = 0; y < h; y++) {
                b.node(hall(x, y), 1 + rnd.nextInt(2));
            }
        }
        int corridors = 0;
        boolean liftDone = false;
        for (int x = 0; x < w; x++) {
            for (int y = 0; y < h; y++) {
                for (int[] d : new int[][] { { 1, 0 }, { 0, 1 } }) {
                    int nx = x + d[0];
                    int ny = y + d[1];
                    if (nx >= w || ny >= h || rnd.nextInt(6) == 0) {
                        continue;
                    }
                    String a = hall(x, y);
                    String z = hall(nx, ny);
                    int kind = rnd.nextInt(4);
                    if (!liftDone && d[1] == 1) {
                        liftDone = true;
                        b.node("lift-a").node("lift-b").edge(a, "lift-a").edge("lift-a", "lift-b").edge("lift-b", z)
                                .area(Kind.LIFT, "lift", 1, "lift-a", "lift-b", a + "-lift-a", "lift-a-lift-b", "lift-b-" + z);
                    } else if (kind == 0) {
                        b.edge(a, z);
                    } else if (kind == 1) {
                        b.edge(a + "-" + z, a, z, 1);
                        b.area(Kind.DOOR, "door-" + a + "-" + z, 1, a + "-" + z);
                    } else {
                        String c = "corridor-" + corridors++;
                        List<String> members = new ArrayList<>();
                        String prev = a;
                        for (int i = 0; i < kind - 1; i++) {
                            String n = c + "-" + i;
                            b.node(n).edge(prev, n);
                            members.add(n);
                            members.add(prev + "-" + n);
                            prev = n;
                        }
                        b.edge(prev, z);
                        members.add(prev + "-" + z);
                        b.area(Kind.CORRIDOR, c, 1, members.toArray(String[]::new));
                    }
                }
            }
        }
        return b.build();
    }

    private static String hall(int x, int y) {
        return "h" + x + "" + y;
    }

    static List<String> shortestPath(TrafficMap map, String from, String to) {
        Map<String, String> parent = new HashMap<>();
        Deque<String> todo = new ArrayDeque<>(List.of(from));
        parent.put(from, from);
        while (!todo.isEmpty()) {
            String at = todo.poll();
            if (at.equals(to)) {
                LinkedList<String> path = new LinkedList<>();
                for (String n = to; !n.equals(from); n = parent.get(n)) {
                    path.addFirst(n);
                }
                path.addFirst(from);
                return path;
            }
            for (String n : map.neighbours(at)) {
                if (parent.putIfAbsent(n, at) == null) {
                    todo.add(n);
                }
            }
        }
        return List.of(from);
    }
}
