package org.triad.planner;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.PriorityQueue;
import java.util.Random;

import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Benchmark main (not a test): a hospital-like numeric problem at N waypoints, planned goal by goal
 * in-process as RefArc's planner component does. A grid of corridors whose segments have lengths of
 * 1-9 m (seeded, so every run plans the same problems), a dock at every tenth waypoint, a battery of
 * 60 drained by each segment's length and recharged to full at a dock, boxes with weights under a
 * payload limit; moves cost their length ({@code (:metric minimize (total-cost))}). Two goals per N: a
 * route to the far corner with a half-empty battery, and a delivery (fetch a box, bring it to a room).
 * Per goal: the engine's plan cost, CPU milliseconds of the planning thread (median of the runs after
 * one warm-up), and, up to {@code OPTIMAL_UP_TO} waypoints, the optimal cost by Dijkstra over
 * (waypoint, battery, phase), which is exact here (integer lengths, recharges to full).
 * {@code java -cp planner/target/classes:planner/target/test-classes org.triad.planner.NumericHospitalBenchmark [N...]}
 */
public final class NumericHospitalBenchmark {
    static final int CAPACITY = 60;
    static final int OPTIMAL_UP_TO = 2000;
    /** Timed runs per goal after the warm-up: 3 up to 200 waypoints, 1 above (the median of one is that run). */
    private static int runs(int n) {
        return n <= 200 ? 3 : 1;
    }
    /** Per solve; {@code -Dtimeout=SECONDS} gives more on a loaded machine (the plans are the same: every budget counts work). */
    private static final Duration TIMEOUT = Duration.ofSeconds(Long.getLong("timeout", 60));

    static final String DOMAIN = """
            (define (domain numeric-hospital)
              (:requirements :strips :typing :numeric-fluents :action-costs)
              (:types waypoint item - object)
              (:predicates (robot-at ?w - waypoint) (adj ?a ?b - waypoint) (dock ?w - waypoint)
                           (item-at ?i - item ?w - waypoint) (holding ?i - item))
              (:functions (distance ?a ?b - waypoint) (battery) (capacity) (load) (payload-limit) (weight ?i - item) (total-cost))
              (:action move
                :parameters (?src ?dst - waypoint)
                :precondition (and (robot-at ?src) (adj ?src ?dst) (>= (battery) (distance ?src ?dst)))
                :effect (and (robot-at ?dst) (not (robot-at ?src)) (decrease (battery) (distance ?src ?dst))
                             (increase (total-cost) (distance ?src ?dst))))
              (:action recharge
                :parameters (?w - waypoint)
                :precondition (and (robot-at ?w) (dock ?w) (< (battery) (capacity)))
                :effect (and (assign (battery) (capacity))))
              (:action load
                :parameters (?i - item ?w - waypoint)
                :precondition (and (robot-at ?w) (item-at ?i ?w) (<= (+ (load) (weight ?i)) (payload-limit)))
                :effect (and (holding ?i) (not (item-at ?i ?w)) (increase (load) (weight ?i))))
              (:action unload
                :parameters (?i - item ?w - waypoint)
                :precondition (and (robot-at ?w) (holding ?i))
                :effect (and (item-at ?i ?w) (not (holding ?i)) (decrease (load) (weight ?i)))))
            """;

    /** A grid map of about n waypoints with seeded segment lengths. */
    record MapGrid(int width, int n, int[][] adj, int[][] len) {
        static MapGrid of(int n, long seed) {
            int width = (int) Math.ceil(Math.sqrt(n));
            Random rnd = new Random(seed);
            List<List<int[]>> edges = new ArrayList<>();
            for (int i = 0; i < n; i++) edges.add(new ArrayList<>());
            for (int i = 0; i < n; i++) {
                int right = i + 1;
                int down = i + width;
                if (right < n && right % width != 0) link(edges, i, right, 1 + rnd.nextInt(9));
                if (down < n) link(edges, i, down, 1 + rnd.nextInt(9));
            }
            int[][] adj = new int[n][];
            int[][] len = new int[n][];
            for (int i = 0; i < n; i++) {
                adj[i] = edges.get(i).stream().mapToInt(e -> e[0]).toArray();
                len[i] = edges.get(i).stream().mapToInt(e -> e[1]).toArray();
            }
            return new MapGrid(width, n, adj, len);
        }

        private static void link(List<List<int[]>> edges, int a, int b, int d) {
            edges.get(a).add(new int[] { b, d });
            edges.get(b).add(new int[] { a, d });
        }

        boolean dock(int w) {
            return w % 10 == 0;
        }
    }

    /** A goal: route to {@code target}, or (when {@code box >= 0}) fetch box from {@code from} and bring it to {@code target}. */
    record Goal(String name, int start, int battery, int from, int target) { }

    static String problem(MapGrid m, Goal g) {
        StringBuilder sb = new StringBuilder("(define (problem p) (:domain numeric-hospital)\n (:objects");
        for (int i = 0; i < m.n; i++) sb.append(" wp").append(i);
        sb.append(" - waypoint box light - item)\n (:init (robot-at wp").append(g.start).append(")\n");
        for (int i = 0; i < m.n; i++) {
            if (m.dock(i)) sb.append(" (dock wp").append(i).append(')');
            for (int k = 0; k < m.adj[i].length; k++) {
                sb.append(" (adj wp").append(i).append(" wp").append(m.adj[i][k]).append(") (= (distance wp").append(i).append(" wp")
                        .append(m.adj[i][k]).append(") ").append(m.len[i][k]).append(')');
            }
            sb.append('\n');
        }
        sb.append(" (item-at light wp").append(g.start).append(") (holding light)");
        if (g.from >= 0) sb.append(" (item-at box wp").append(g.from).append(')');
        sb.append(" (= (battery) ").append(g.battery).append(") (= (capacity) ").append(CAPACITY).append(") (= (load) 3) (= (payload-limit) 10)")
                .append(" (= (weight box) 7) (= (weight light) 3) (= (total-cost) 0))\n");
        sb.append(" (:goal (and ").append(g.from >= 0 ? "(item-at box wp" + g.target + ")" : "(robot-at wp" + g.target + ")").append("))\n");
        return sb.append(" (:metric minimize (total-cost)))\n").toString();
    }

    /**
     * The optimal cost by Dijkstra over (waypoint, battery, phase): phase 0 before the box is taken, 1
     * while it is carried (it can only be taken after the light item is put down: the payload limit),
     * 2 done. Recharging and (un)loading cost nothing; moves their length.
     */
    static int optimal(MapGrid m, Goal g) {
        int phases = 3;
        int size = m.n * (CAPACITY + 1) * phases;
        int[] dist = new int[size];
        Arrays.fill(dist, Integer.MAX_VALUE);
        PriorityQueue<int[]> q = new PriorityQueue<>((a, b) -> Integer.compare(a[0], b[0]));
        int start = (g.start * (CAPACITY + 1) + g.battery) * phases;
        dist[start] = 0;
        q.add(new int[] { 0, start });
        while (!q.isEmpty()) {
            int[] top = q.poll();
            int s = top[1];
            if (top[0] > dist[s]) continue;
            int phase = s % phases;
            int b = (s / phases) % (CAPACITY + 1);
            int w = s / phases / (CAPACITY + 1);
            if (g.from < 0 ? w == g.target : phase == 2) return top[0];
            List<int[]> next = new ArrayList<>();
            for (int k = 0; k < m.adj[w].length; k++) if (b >= m.len[w][k]) next.add(new int[] { m.adj[w][k], b - m.len[w][k], phase, m.len[w][k] });
            if (m.dock(w) && b < CAPACITY) next.add(new int[] { w, CAPACITY, phase, 0 });
            if (g.from >= 0 && phase == 0 && w == g.from) next.add(new int[] { w, b, 1, 0 }); // put the light item down anywhere first: free
            if (phase == 1 && w == g.target) next.add(new int[] { w, b, 2, 0 });
            for (int[] x : next) {
                int t = (x[0] * (CAPACITY + 1) + x[1]) * phases + x[2];
                int d = top[0] + x[3];
                if (d < dist[t]) {
                    dist[t] = d;
                    q.add(new int[] { d, t });
                }
            }
        }
        return -1;
    }

    public static void main(String[] args) {
        int[] sizes = args.length == 0 ? new int[] { 100, 200, 500, 1000, 2000 } : Arrays.stream(args).mapToInt(Integer::parseInt).toArray();
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        Domain domain = PddlParser.parseDomain(DOMAIN, "numeric-hospital.pddl");
        System.out.printf("Java %s, %d cores, load average at start %.1f; CPU ms of the planning thread (grounding and search), median of 3 runs"
                + " after a warm-up up to N = 200, one run above%n%n", System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        System.out.println("| N | goal | status | steps | recharges | cost | optimal | ratio | states evaluated | CPU ms | wall ms |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        for (int n : sizes) {
            MapGrid m = MapGrid.of(n, 22 + n);
            int far = n - 1;
            List<Goal> goals = List.of(new Goal("IsAt(far corner), battery 30", 0, 30, -1, far),
                    new Goal("Delivered(box, room)", 0, 40, n / 2 + m.width / 2, far - m.width / 3));
            for (Goal g : goals) {
                Problem p = PddlParser.parseProblem(problem(m, g), "numeric-hospital-" + n + ".pddl");
                TriadEngine engine = new TriadEngine();
                SolveResult r = engine.solve(domain, p, TIMEOUT);
                int runs = runs(n);
                long[] cpuNs = new long[runs];
                long[] wallNs = new long[runs];
                for (int i = 0; i < runs && r.isSolved(); i++) {
                    long c0 = cpu.getCurrentThreadCpuTime();
                    long w0 = System.nanoTime();
                    r = engine.solve(domain, p, TIMEOUT);
                    cpuNs[i] = cpu.getCurrentThreadCpuTime() - c0;
                    wallNs[i] = System.nanoTime() - w0;
                }
                Arrays.sort(cpuNs);
                Arrays.sort(wallNs);
                String status = r.isBestSoFar() ? "best so far" : r.status().toString();
                String opt = "-";
                String ratio = "-";
                double cost = Double.NaN;
                if (r.isSolved()) {
                    PlanValidator.Report v = PlanValidator.validate(domain, p, r.plan());
                    if (!v.valid()) status = "INVALID: " + v.message();
                    cost = PlanValidator.metricValue(domain, p, r.plan()).orElse(Double.NaN);
                }
                if (n <= OPTIMAL_UP_TO) {
                    int o = optimal(m, g);
                    opt = Integer.toString(o);
                    if (!Double.isNaN(cost) && o > 0) ratio = String.format(Locale.ROOT, "%.2f", cost / o);
                }
                long recharges = r.isSolved() ? r.plan().steps().stream().filter(s -> s.name().equals("recharge")).count() : 0;
                System.out.printf(Locale.ROOT, "| %d | %s | %s | %s | %s | %s | %s | %s | %d | %s | %s |%n", n, g.name, status,
                        r.isSolved() ? r.plan().length() : "-", r.isSolved() ? recharges : "-", Double.isNaN(cost) ? "-" : String.format(Locale.ROOT, "%.0f", cost),
                        opt, ratio, r.stats().evaluated(), r.isSolved() ? String.format(Locale.ROOT, "%.1f", cpuNs[runs / 2] / 1e6) : "-",
                        r.isSolved() ? String.format(Locale.ROOT, "%.1f", wallNs[runs / 2] / 1e6) : String.format(Locale.ROOT, "%s", r.message()));
            }
        }
    }
}
