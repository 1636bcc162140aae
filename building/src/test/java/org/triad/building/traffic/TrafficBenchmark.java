package org.triad.building.traffic;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Random;
import java.util.Set;

import org.triad.building.traffic.Decision.Granted;
import org.triad.building.traffic.Decision.Refused;
import org.triad.building.traffic.Resource.Kind;

/**
 * The traffic benchmark: fleets of 2, 5, 10 and 20 robots, 8 simulated hours each of random deliveries,
 * guides and patrols between random rooms on two floors of a hospital (per floor a ring of corridors as in
 * the hospital model: wide north and south corridors, single-lane west and east corridors, a fire door,
 * six rooms behind doors for one; a lift for one between the floors; at most 17 robots admitted to a floor,
 * a zone), with the reservation table and without it. A kinematic simulation of its own (robots at 1 m/s along the map's edges, 0.5 s steps; the
 * one-building dyn4j simulation is issue #20's): a <em>collision</em> is two robots on a resource for one
 * (more than its capacity) at once; without reservations both then stand 30 s to recover (the jam).
 * A <em>standstill</em> is 60 simulated seconds in which no robot with a task moved.
 *
 * <pre>
 * mvn -B -q -pl building -am test-compile
 * java -cp building/target/classes:building/target/test-classes org.triad.building.traffic.TrafficBenchmark [hours] [seed]
 * </pre>
 * Options: {@code -Dtraffic.fleets=20,10} (fleet sizes), {@code -Dtraffic.floorZone=N} (robots admitted per floor,
 * 0 for no limit), {@code -Dtraffic.why} (per run, why requests were refused or timed out), {@code -Dtraffic.debug}
 * (every robot at each standstill).
 */
public final class TrafficBenchmark {
    private static final double DT = 0.5;
    private static final double SPEED = 1.0;
    private static final double RIDE = 30;
    private static final double DWELL = 10;
    private static final double WAIT_BOUND = 60;
    private static final double RECOVERY = 30;
    /** Robots admitted to one floor at once (of its 18 places in halls and rooms, so a full floor keeps one to swap through), 0 for no limit. */
    private static final int FLOOR_ZONE = Integer.getInteger("traffic.floorZone", 17);

    private final TrafficMap map;
    private final Map<String, Double> length = new HashMap<>();
    private final List<String> rooms = new ArrayList<>();

    private TrafficBenchmark() {
        TrafficMap.Builder b = TrafficMap.builder();
        for (int f = 1; f <= 2; f++) {
            String p = "f" + f + ".";
            for (int c = 1; c <= 6; c++) {
                b.node(p + "c" + c, 2);
            }
            wide(b, p + "c1", p + "c2", 8);
            b.edge(p + "c2", p + "c3");
            length.put(p + "c2-" + p + "c3", 8.0);
            b.area(Kind.DOOR, p + "fireDoor", 1, p + "c2-" + p + "c3");
            wide(b, p + "c4", p + "c5", 8);
            wide(b, p + "c5", p + "c6", 8);
            lane(b, Kind.CORRIDOR, p + "west", p + "c1", p + "c4", 8);
            lane(b, Kind.CORRIDOR, p + "east", p + "c3", p + "c6", 8);
            String[] names = { "storage", "xray", "ward1", "lobby", "ward3", "ward2" };
            for (int r = 0; r < 6; r++) {
                String room = p + names[r];
                b.node(room, 1);
                rooms.add(room);
                lane(b, Kind.DOOR, room + "Door", room, p + "c" + (r + 1), 3);
            }
            b.node(p + "lift");
            b.edge(p + "c6", p + "lift");
            length.put(p + "c6-" + p + "lift", 3.0);
            if (FLOOR_ZONE > 0) { // admission: no more robots on a floor than leave room to pass each other
                List<String> members = new ArrayList<>();
                for (String n : b.nodeIds()) {
                    if (n.startsWith(p)) {
                        members.add(n);
                    }
                }
                for (String e : b.edgeIds()) {
                    if (e.startsWith(p)) {
                        members.add(e);
                    }
                }
                b.area(Kind.ZONE, "floor" + f, FLOOR_ZONE, members.toArray(String[]::new));
            }
        }
        b.edge("ride", "f1.lift", "f2.lift", 1);
        length.put("ride", RIDE * SPEED);
        b.area(Kind.LIFT, "lift", 1, "f1.lift", "f2.lift", "ride", "f1.c6-f1.lift", "f2.c6-f2.lift");
        map = b.build();
    }

    private void wide(TrafficMap.Builder b, String a, String z, double m) {
        b.edge(a + "-" + z, a, z, 2);
        length.put(a + "-" + z, m);
    }

    private void lane(TrafficMap.Builder b, Kind kind, String area, String a, String z, double m) {
        b.edge(a, z);
        length.put(a + "-" + z, m);
        b.area(kind, area, 1, a + "-" + z);
    }

    private double len(String a, String z) {
        return length.get(map.edge(a, z).orElseThrow().id());
    }

    /** The cheapest route by travel time plus, under traffic control, each step's expected wait (the congestion hook). */
    private List<String> route(String from, String to, ReservationTable table) {
        Map<String, Double> dist = new HashMap<>();
        Map<String, String> prev = new HashMap<>();
        PriorityQueue<Map.Entry<String, Double>> q = new PriorityQueue<>(Map.Entry.comparingByValue());
        dist.put(from, 0.0);
        q.add(Map.entry(from, 0.0));
        while (!q.isEmpty()) {
            Map.Entry<String, Double> e = q.poll();
            String at = e.getKey();
            if (e.getValue() > dist.get(at)) {
                continue;
            }
            for (String n : map.neighbours(at)) {
                double cost = len(at, n) / SPEED + (table == null ? 0 : Math.min(table.expectedWait(at, n), 1e6));
                if (e.getValue() + cost < dist.getOrDefault(n, Double.POSITIVE_INFINITY)) {
                    dist.put(n, e.getValue() + cost);
                    prev.put(n, at);
                    q.add(Map.entry(n, e.getValue() + cost));
                }
            }
        }
        List<String> r = new ArrayList<>();
        for (String n = to; n != null; n = prev.get(n)) {
            r.add(0, n);
        }
        return r;
    }

    private static final class Bot {
        final String name;
        final List<String> destinations = new ArrayList<>();
        List<String> route = List.of();
        int at;
        int baseEnd;
        double onEdge;
        double dwell;
        double stuckUntil;
        double retryAt;
        boolean waiting;
        boolean yielding;
        double taskWait;

        Bot(String name) {
            this.name = name;
        }
    }

    private record Result(int collisions, int standstills, int cycles, double tasksPerHour, List<Double> taskWaits, Map<Kind, List<Double>> waits,
            double cpuMicrosPerRobotHour, double cpuMicrosPerGrant) {
    }

    /** Lift rides and, for {@code -Dtraffic.why}, why requests were refused or timed out (robot names and floors left out), counted per run. */
    private static final Map<String, Integer> EVENTS = new HashMap<>();

    private Result run(int fleet, double hours, boolean reservations, long seed) {
        Random rnd = new Random(seed);
        double[] now = { 0 };
        ReservationTable table = reservations ? new ReservationTable(map, () -> now[0]) : null;
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        long cpuNanos = 0;
        long grants = 0;
        List<Bot> bots = new ArrayList<>();
        List<String> starts = new ArrayList<>(map.nodeIds().stream().filter(n -> n.matches("f\\d\\.c\\d")).toList());
        for (int i = 0; i < fleet; i++) {
            Bot b = new Bot("r" + i);
            String start = starts.get(i % starts.size());
            b.route = List.of(start);
            if (table != null) {
                table.place(b.name, start);
            }
            bots.add(b);
        }
        int collisions = 0;
        int standstills = 0;
        int cycles = 0;
        int tasks = 0;
        List<Double> taskWaits = new ArrayList<>();
        Set<String> contacts = new HashSet<>();
        double lastMove = 0;
        for (now[0] = 0; now[0] < hours * 3600; now[0] += DT) {
            boolean moved = false;
            boolean anyTask = false;
            for (Bot b : bots) {
                String here = b.route.get(b.at);
                if (b.dwell > 0) {
                    b.dwell -= DT;
                    continue;
                }
                if (b.at == b.route.size() - 1) { // arrived: next destination, or a new task
                    if (!b.destinations.isEmpty() && b.destinations.get(0).equals(here)) {
                        b.destinations.remove(0);
                        if (b.yielding) {
                            b.yielding = false;
                            continue;
                        }
                        b.dwell = DWELL;
                        if (b.destinations.isEmpty()) {
                            tasks++;
                            taskWaits.add(b.taskWait);
                            b.taskWait = 0;
                        }
                        continue;
                    }
                    if (b.destinations.isEmpty()) {
                        newTask(b, rnd);
                    }
                    if (now[0] < b.retryAt) {
                        continue;
                    }
                    long t0 = cpu.getCurrentThreadCpuTime();
                    b.route = route(here, b.destinations.get(0), table);
                    b.at = 0;
                    b.onEdge = 0;
                    b.baseEnd = 0;
                    if (table != null && b.route.size() > 1) {
                        Decision d = table.request(b.name, b.route);
                        if (d instanceof Granted g) {
                            b.baseEnd = g.stretch().size() - 1;
                            grants++;
                        } else if (d instanceof Refused r) {
                            EVENTS.merge("refused-start " + r.reason().replaceAll("r\\d+", "r").replaceAll("'f\\d\\.", "'"), 1, Integer::sum);
                            b.route = List.of(here);
                            yieldFirst(table, b, here, null, rnd);
                            makeWay(table, bots, b, r, now[0], rnd);
                            b.retryAt = now[0] + rnd.nextInt(5); // re-plan: out of the way first
                        } else {
                            b.waiting = true;
                        }
                    } else {
                        b.baseEnd = b.route.size() - 1;
                    }
                    cpuNanos += cpu.getCurrentThreadCpuTime() - t0;
                    continue;
                }
                anyTask = true;
                if (b.stuckUntil > now[0]) {
                    continue;
                }
                if (b.at >= b.baseEnd) {
                    b.taskWait += DT;
                    continue;
                }
                String next = b.route.get(b.at + 1);
                b.onEdge += SPEED * DT;
                moved = true;
                if (b.onEdge >= len(here, next)) {
                    if (map.edge(here, next).orElseThrow().id().equals("ride")) {
                        EVENTS.merge("rides", 1, Integer::sum);
                    }
                    b.onEdge = 0;
                    b.at++;
                    if (table != null) {
                        long t0 = cpu.getCurrentThreadCpuTime();
                        for (Granted g : table.passed(b.name, next).granted()) {
                            Bot o = bots.get(Integer.parseInt(g.robot().substring(1)));
                            o.baseEnd += g.stretch().size() - 1;
                            o.waiting = false;
                            grants++;
                        }
                        cpuNanos += cpu.getCurrentThreadCpuTime() - t0;
                    }
                }
            }
            if (table != null) {
                long t0 = cpu.getCurrentThreadCpuTime();
                for (Bot b : bots) { // ask one stretch ahead; give up waits over the bound and re-plan
                    if (!b.waiting && b.baseEnd < b.route.size() - 1 && b.baseEnd - b.at <= lastStretch(b)) {
                        Decision d = table.request(b.name, b.route.subList(b.baseEnd, b.route.size()));
                        if (d instanceof Granted g) {
                            b.baseEnd += g.stretch().size() - 1;
                            grants++;
                        } else if (d instanceof Refused r) {
                            EVENTS.merge("refused-ahead " + r.reason().replaceAll("r\\d+", "r").replaceAll("'f\\d\\.", "'"), 1, Integer::sum);
                            truncate(table, b, now[0], rnd);
                            makeWay(table, bots, b, r, now[0], rnd);
                        } else {
                            b.waiting = true;
                        }
                    }
                }
                for (Wait w : table.overdue(WAIT_BOUND)) {
                    Bot b = bots.get(Integer.parseInt(w.robot().substring(1)));
                    EVENTS.merge("overdue " + w.blocking().stream().map(x -> x.kind().toString()).sorted().distinct().toList(), 1, Integer::sum);
                    table.cancel(b.name).granted().forEach(g -> {
                        Bot o = bots.get(Integer.parseInt(g.robot().substring(1)));
                        o.baseEnd += g.stretch().size() - 1;
                        o.waiting = false;
                    });
                    b.waiting = false;
                    if (b.at == b.baseEnd) {
                        truncate(table, b, now[0], rnd);
                    }
                }
                cpuNanos += cpu.getCurrentThreadCpuTime() - t0;
                if (!Graphs.cycle(table.waitsFor()).isEmpty()) {
                    cycles++;
                }
            }
            collisions += contacts(bots, contacts, now[0]);
            if (moved || !anyTask) {
                lastMove = now[0];
            } else if (now[0] - lastMove > 60) {
                standstills++;
                lastMove = now[0];
                if (System.getProperty("traffic.debug") != null && table != null) {
                    System.out.println("standstill at " + now[0] + ": " + table.waits().stream().map(Wait::reason).toList());
                    for (Bot b : bots) {
                        System.out.println("  " + b.name + " at " + b.route.get(b.at) + " route " + b.route + " base " + b.baseEnd + " dest " + b.destinations
                                + " waiting " + b.waiting + " retry " + b.retryAt + " dwell " + b.dwell);
                    }
                }
            }
        }
        Map<Kind, List<Double>> waits = new HashMap<>();
        if (table != null) {
            for (Kind k : Kind.values()) {
                waits.put(k, table.stats().waits(k));
            }
        }
        return new Result(collisions, standstills, cycles, tasks / hours, taskWaits, waits, cpuNanos / 1e3 / fleet / hours,
                grants == 0 ? 0 : cpuNanos / 1e3 / grants);
    }

    /** How many nodes of its base ahead a robot has when it is in its last granted stretch (the next stop node). */
    private int lastStretch(Bot b) {
        int n = 0;
        for (int i = b.at + 1; i <= b.baseEnd; i++) {
            n++;
            if (map.isStop(b.route.get(i)) && i < b.baseEnd) {
                return -1;
            }
        }
        return n;
    }

    /**
     * A robot refused because its wait would close a cycle, and with no way out of its own (a dead-end room),
     * asks the others of the cycle that wait at their decision points to make way: their waits are withdrawn
     * and they yield to a side node first (what a dispatcher does; the table only refuses).
     */
    private void makeWay(ReservationTable table, List<Bot> bots, Bot refused, Refused r, double now, Random rnd) {
        if (refused.yielding || r.cycle().isEmpty()) {
            return;
        }
        for (String name : r.cycle().subList(1, r.cycle().size())) {
            Bot o = bots.get(Integer.parseInt(name.substring(1)));
            if (o.waiting && o.at == o.baseEnd) {
                for (Granted g : table.cancel(o.name).granted()) {
                    Bot x = bots.get(Integer.parseInt(g.robot().substring(1)));
                    x.baseEnd += g.stretch().size() - 1;
                    x.waiting = false;
                }
                o.waiting = false;
                truncate(table, o, now, rnd);
            }
        }
    }

    /** The robot's request failed at its decision point: the route ends there, and it re-plans, out of the way first. */
    private void truncate(ReservationTable table, Bot b, double now, Random rnd) {
        String blocked = b.baseEnd + 1 < b.route.size() ? b.route.get(b.baseEnd + 1) : null;
        b.route = List.copyOf(b.route.subList(0, b.baseEnd + 1));
        yieldFirst(table, b, b.route.get(b.baseEnd), blocked, rnd);
        b.retryAt = now + rnd.nextInt(5);
    }

    /**
     * Yields: a stop node next to where the robot waits, with room and not the way it was refused, becomes its
     * first destination (what a re-plan does after a refusal: out of the way, then on).
     */
    private void yieldFirst(ReservationTable table, Bot b, String here, String refusedWay, Random rnd) {
        if (b.yielding) {
            return;
        }
        List<String> side = new ArrayList<>();
        for (String n : map.neighbours(here)) {
            if (map.isStop(n) && !n.equals(refusedWay) && !n.equals(b.destinations.isEmpty() ? null : b.destinations.get(0))
                    && map.standing(n).stream().allMatch(r -> table.holders(r).size() < r.capacity())) {
                side.add(n);
            }
        }
        if (!side.isEmpty()) {
            b.destinations.add(0, side.get(rnd.nextInt(side.size())));
            b.yielding = true;
        }
    }

    private void newTask(Bot b, Random rnd) {
        int kind = rnd.nextInt(3);
        if (kind == 0) { // delivery: fetch from a storage, bring to a room
            b.destinations.add(rnd.nextBoolean() ? "f1.storage" : "f2.storage");
            b.destinations.add(rooms.get(rnd.nextInt(rooms.size())));
        } else if (kind == 1) { // guide: from one room to another
            b.destinations.add(rooms.get(rnd.nextInt(rooms.size())));
            b.destinations.add(rooms.get(rnd.nextInt(rooms.size())));
        } else { // patrol: three junctions
            for (int i = 0; i < 3; i++) {
                b.destinations.add("f" + (1 + rnd.nextInt(2)) + ".c" + (1 + rnd.nextInt(6)));
            }
        }
    }

    /** New contacts: a resource holding more robots than its capacity; without reservations the robots then stand to recover. */
    private int contacts(List<Bot> bots, Set<String> ongoing, double now) {
        Map<Resource, List<Bot>> on = new HashMap<>();
        for (Bot b : bots) {
            String here = b.route.get(b.at);
            Set<Resource> occ = b.onEdge > 0 ? map.step(here, b.route.get(b.at + 1)) : map.standing(here);
            for (Resource r : occ) {
                if (r.kind() != Kind.ZONE) { // a floor over its admission limit is crowded, not a contact
                    on.computeIfAbsent(r, k -> new ArrayList<>()).add(b);
                }
            }
        }
        int fresh = 0;
        Set<String> current = new HashSet<>();
        for (Map.Entry<Resource, List<Bot>> e : on.entrySet()) {
            if (e.getValue().size() > e.getKey().capacity()) {
                String key = e.getKey() + e.getValue().stream().map(b -> b.name).sorted().toList().toString();
                current.add(key);
                if (!ongoing.contains(key)) {
                    fresh++;
                    e.getValue().forEach(b -> b.stuckUntil = now + RECOVERY);
                }
            }
        }
        ongoing.clear();
        ongoing.addAll(current);
        return fresh;
    }

    public static void main(String[] args) {
        double hours = args.length > 0 ? Double.parseDouble(args[0]) : 8;
        long seed = args.length > 1 ? Long.parseLong(args[1]) : 42;
        TrafficBenchmark bench = new TrafficBenchmark();
        System.out.printf(Locale.ROOT, "traffic benchmark: %.1f simulated hours per fleet, seed %d, kinematic simulation (see javadoc)%n", hours, seed);
        System.out.printf(Locale.ROOT, "%-6s | %-12s | %10s | %11s | %6s | %7s | %11s | %-26s | %-20s | %-20s | %-20s | %12s | %11s%n", "robots",
                "reservations", "collisions", "standstills", "cycles", "tasks/h", "lift rides/h", "wait per task med/p95/max", "lift med/p95/max",
                "door med/p95/max", "corridor med/p95/max", "cpu us/robot-h", "cpu us/grant");
        int[] fleets = System.getProperty("traffic.fleets") == null ? new int[] { 2, 5, 10, 20 }
                : java.util.Arrays.stream(System.getProperty("traffic.fleets").split(",")).mapToInt(Integer::parseInt).toArray();
        for (int fleet : fleets) {
            for (boolean res : new boolean[] { true, false }) {
                EVENTS.clear();
                Result r = bench.run(fleet, hours, res, seed);
                if (System.getProperty("traffic.why") != null) {
                    EVENTS.entrySet().stream().filter(e -> !e.getKey().equals("rides")).sorted((a, c) -> c.getValue() - a.getValue()).limit(10).forEach(e -> System.out.println("   " + e.getValue() + " " + e.getKey()));
                }
                System.out.printf(Locale.ROOT, "%-6d | %-12s | %10d | %11d | %6d | %7.1f | %11.1f | %-26s | %-20s | %-20s | %-20s | %12.1f | %11.1f%n", fleet,
                        res ? "yes" : "no", r.collisions(), r.standstills(), r.cycles(), r.tasksPerHour(), EVENTS.getOrDefault("rides", 0) / hours, res ? q(r.taskWaits()) : "-",
                        res ? q(r.waits().get(Kind.LIFT)) : "-", res ? q(r.waits().get(Kind.DOOR)) : "-",
                        res ? q(r.waits().get(Kind.CORRIDOR)) : "-", r.cpuMicrosPerRobotHour(), r.cpuMicrosPerGrant());
            }
        }
    }

    private static String q(List<Double> xs) {
        return String.format(Locale.ROOT, "%.0f/%.0f/%.0f s", TrafficStats.quantile(xs, 0.5), TrafficStats.quantile(xs, 0.95),
                TrafficStats.quantile(xs, 1.0));
    }
}
