package org.triad.sim;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;

/**
 * Benchmark (not a test): a delivery-like scenario - the robot fetches two items from storage and
 * delivers them to two rooms while six people wander, a door closes on its route and people block the
 * corridor for a while - repeated; prints simulated seconds, wall seconds and the real-time factor per run
 * and their medians. See sim/BENCHMARK.md for the command line.
 *
 * <p>Arguments: {@code [runs=7] [warmups=3] [trace=true]}.
 */
public final class DeliveryBenchmark {

    private DeliveryBenchmark() {
    }

    /** Runs one delivery and returns the finished simulation. */
    static Simulation deliver(long seed, boolean trace) {
        Simulation sim = Simulation.builder(FloorPlans.corridorWithRooms()).seed(seed).recordTrace(trace).build();
        Robot robot = sim.addRobot("robot", "corridorWest", RobotSpec.defaults());
        String[] starts = {"room1Front", "room3Front", "room4", "room5", "room6", "room3"};
        for (int i = 0; i < starts.length; i++) {
            sim.addPerson("person" + (i + 1), starts[i], PersonSpec.defaults().withMaxSpeed(0.8 + 0.1 * (i % 4))).wander();
        }
        sim.at(25).closeDoor("room1-room2").at(120).openDoor("room1-room2");
        sim.at(60).blockSegment("room4Front", "room5Front", 4, 8);
        go(robot, "storage");
        require(robot.pick("item1"));
        go(robot, "room2");
        require(robot.place("item1"));
        go(robot, "storage");
        require(robot.pick("item2"));
        go(robot, "room5");
        require(robot.place("item2"));
        go(robot, "corridorWest");
        return sim;
    }

    /** Like an application would: after a failed move (closed door, blocked) try again; the robot replans. */
    private static void go(Robot robot, String waypoint) {
        ActionResult r = robot.moveTo(waypoint);
        for (int attempt = 1; attempt < 4 && !r.success(); attempt++) {
            r = robot.moveTo(waypoint);
        }
        require(r);
    }

    private static void require(ActionResult r) {
        if (!r.success()) {
            throw new IllegalStateException("benchmark scenario broke: " + r);
        }
    }

    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 7;
        int warmups = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        boolean trace = args.length <= 2 || Boolean.parseBoolean(args[2]);
        for (int i = 0; i < warmups; i++) {
            deliver(1000 + i, trace);
        }
        System.out.printf(Locale.ROOT, "delivery benchmark: %d runs after %d warm-ups, trace %s, step 1/60 s%n", runs,
                warmups, trace ? "on" : "off");
        System.out.printf(Locale.ROOT, "%4s %6s %9s %9s %9s %7s %8s %8s%n", "run", "seed", "sim [s]", "wall [s]",
                "cpu [s]", "steps", "RTF", "RTF cpu");
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        double[] simSeconds = new double[runs];
        double[] wallSeconds = new double[runs];
        double[] rtf = new double[runs];
        double[] rtfCpu = new double[runs];
        for (int i = 0; i < runs; i++) {
            long seed = i + 1;
            long c0 = threads.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            Simulation sim = deliver(seed, trace);
            double wall = (System.nanoTime() - t0) / 1e9;
            double cpu = (threads.getCurrentThreadCpuTime() - c0) / 1e9;
            simSeconds[i] = sim.time();
            wallSeconds[i] = wall;
            rtf[i] = sim.time() / wall;
            rtfCpu[i] = sim.time() / cpu;
            System.out.printf(Locale.ROOT, "%4d %6d %9.1f %9.3f %9.3f %7d %7.0fx %7.0fx%n", i + 1, seed, sim.time(), wall,
                    cpu, sim.steps(), rtf[i], rtfCpu[i]);
        }
        System.out.printf(Locale.ROOT, "median: sim %.1f s, wall %.3f s, real-time factor %.0fx (per CPU second of the "
                + "simulation thread: %.0fx)%n", median(simSeconds), median(wallSeconds), median(rtf), median(rtfCpu));
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
