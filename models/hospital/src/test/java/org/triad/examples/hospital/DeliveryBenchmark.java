package org.triad.examples.hospital;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import generated.hospital.tasks.CollectAndDeliver;

/**
 * Benchmark main (not a test): the real-time factor of the hospital delivery
 * {@code CollectAndDeliver(gauze, storage, ward1)} run through RefArc on the simulation, i.e. simulated
 * seconds per wall-clock second including the runtime planning of every goal, and per CPU second of the
 * process (all threads, GC and JIT included; on a shared machine the wall clock also counts waiting for a core). Arguments: {@code [runs=9] [warmups=10]}. See BENCHMARK.md.
 */
public final class DeliveryBenchmark {
    private DeliveryBenchmark() {
    }

    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 9;
        int warmups = args.length > 1 ? Integer.parseInt(args[1]) : 10;
        if (runs < 1 || warmups < 0) {
            throw new IllegalArgumentException("usage: DeliveryBenchmark [runs >= 1] [warmups >= 0]");
        }
        com.sun.management.OperatingSystemMXBean os =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        for (int i = 0; i < warmups; i++) {
            run(100 + i, os);
        }
        System.out.printf(Locale.ROOT, "hospital delivery through RefArc on the simulation: %d runs after %d warm-ups, step 1/60 s, trace on%n",
                runs, warmups);
        System.out.printf(Locale.ROOT, "%4s %6s %9s %9s %9s %7s %8s %9s%n", "run", "seed", "sim [s]", "wall [s]", "cpu [s]", "steps", "RTF",
                "RTF cpu");
        List<double[]> rows = new ArrayList<>();
        for (int i = 1; i <= runs; i++) {
            double[] r = run(i, os);
            rows.add(r);
            System.out.printf(Locale.ROOT, "%4d %6d %9.1f %9.3f %9.3f %7d %7.0fx %8.0fx%n", i, i, r[0], r[1], r[2], (long) r[3], r[0] / r[1],
                    r[0] / r[2]);
        }
        System.out.printf(Locale.ROOT, "median: sim %.1f s, wall %.3f s, cpu %.3f s, real-time factor %.0fx (per CPU second %.0fx)%n",
                median(rows, 0), median(rows, 1), median(rows, 2), medianRatio(rows, 1), medianRatio(rows, 2));
    }

    /** One delivery: {simulated s, wall s, cpu s, steps}. */
    private static double[] run(long seed, com.sun.management.OperatingSystemMXBean os) {
        HospitalSimulation h = new HospitalSimulation(seed);
        HospitalObjects o = h.objects();
        long cpu0 = os.getProcessCpuTime();
        long wall0 = System.nanoTime();
        HospitalRun run = h.run(new CollectAndDeliver(o.item("gauze"), o.room("storage"), o.room("ward1")));
        double wall = (System.nanoTime() - wall0) / 1e9;
        double cpu = (os.getProcessCpuTime() - cpu0) / 1e9;
        if (!run.completed()) {
            throw new IllegalStateException("the delivery did not complete: " + run.refArc().log());
        }
        return new double[] {run.simSeconds(), wall, cpu, h.sim().steps()};
    }

    private static double median(List<double[]> rows, int column) {
        return median(rows.stream().mapToDouble(r -> r[column]).toArray());
    }

    private static double medianRatio(List<double[]> rows, int column) {
        return median(rows.stream().mapToDouble(r -> r[0] / r[column]).toArray());
    }

    private static double median(double[] values) {
        double[] v = values.clone();
        Arrays.sort(v);
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }
}
