package org.triad.examples.hospital.vda5050;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.triad.examples.hospital.HospitalRun;
import org.triad.examples.hospital.HospitalSimulation;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.Status;
import org.triad.runtime.app.GroundAction;
import org.triad.vda5050.broker.MosquittoBroker;
import org.triad.vda5050.master.MasterControl;
import org.triad.vda5050.master.VdaTimeouts;

import generated.hospital.tasks.CollectAndDeliver;
import generated.hospital.tasks.Patrol;

/**
 * Benchmark main (not a test), see vda5050/BENCHMARK.md: the hospital delivery through a real Mosquitto vs.
 * in-process (wall time, simulated-time factor, same seed, same plan), state messages per second per robot,
 * latency from an order to the first state acknowledging it (median, p99), and 20 robots in ONE building (one
 * simulation, one clock: {@code HospitalAgvMain --count 20}) on one broker, each patrolling three rooms at the
 * same time, with the simulated/real time ratio the building achieved and the CPU split between broker, building
 * and master. Arguments: {@code [runs=5] [robots=20] [speed=10|max]}.
 */
public final class VdaBenchmark {
    private VdaBenchmark() {
    }

    private record Delivery(boolean completed, double simSeconds, double wallSeconds, List<GroundAction> plan, long states,
            List<Long> ackNanos) {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        int robots = args.length > 1 ? Integer.parseInt(args[1]) : 20;
        String fleetSpeed = args.length > 2 ? args[2] : "10";
        Path dir = Path.of("target", "vda5050-benchmark");
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"))) {
            // warm-up of both paths
            inProcess();
            throughBroker(broker, "warmup", Double.POSITIVE_INFINITY);
            System.out.printf(Locale.ROOT, "delivery CollectAndDeliver(gauze, storage, ward1), seed 42, %d runs each (medians)%n", runs);
            System.out.printf(Locale.ROOT, "%-34s %8s %9s %9s %9s %10s %9s %9s%n", "path", "sim [s]", "wall [s]", "RTF", "actions",
                    "states/s", "ack p50", "ack p99");
            List<Delivery> local = new ArrayList<>();
            for (int i = 0; i < runs; i++) {
                local.add(inProcess());
            }
            print("in-process simulation", local);
            for (double speed : new double[] { Double.POSITIVE_INFINITY, 10 }) {
                List<Delivery> remote = new ArrayList<>();
                for (int i = 0; i < runs; i++) {
                    remote.add(throughBroker(broker, "bench-" + (Double.isInfinite(speed) ? "max" : (long) speed) + "-" + i, speed));
                }
                print(Double.isInfinite(speed) ? "VDA 5050 via Mosquitto, unpaced" : "VDA 5050 via Mosquitto, 10x paced", remote);
                if (!remote.get(0).plan().equals(local.get(0).plan())) {
                    System.out.println("  PLAN DIFFERS: " + remote.get(0).plan() + " vs " + local.get(0).plan());
                } else {
                    System.out.println("  same plan as in-process (" + local.get(0).plan().size() + " actions)");
                }
            }
            fleet(broker, robots, fleetSpeed, dir);
        }
    }

    private static Delivery inProcess() {
        HospitalSimulation h = new HospitalSimulation(42);
        List<GroundAction> plan = new ArrayList<>();
        HospitalRun run = h.run(new CollectAndDeliver(h.objects().item("gauze"), h.objects().room("storage"), h.objects().room("ward1")),
                s -> {
                    if (s instanceof Status.ActionStarted a) {
                        plan.add(a.action());
                    }
                });
        return new Delivery(run.completed(), run.simSeconds(), run.wallSeconds(), plan, 0, List.of());
    }

    private static Delivery throughBroker(MosquittoBroker broker, String serial, double speed) {
        try (SimulatedAgv agv = new SimulatedAgv(broker.url(), serial, 42, speed, null, line -> { }).start();
                MasterControl master = MasterControl.connect(broker.url(), VdaTimeouts.defaults(), line -> { })) {
            VdaHospital h = new VdaHospital(master, serial);
            h.courier().agv().awaitOnline();
            List<GroundAction> plan = new ArrayList<>();
            List<Long> acks = new CopyOnWriteArrayList<>();
            long states0 = agv.statesSent();
            double sim0 = agv.hospital().clock().orElseThrow().call(s -> s.time());
            long t0 = System.nanoTime();
            RefArcRun run = h.run(new CollectAndDeliver(h.objects().item("gauze"), h.objects().room("storage"), h.objects().room("ward1")),
                    s -> {
                        if (s instanceof Status.ActionStarted a) {
                            plan.add(a.action());
                        } else if (s instanceof Status.ActionSucceeded && h.courier().agv().lastOrderAcknowledgedNanos() >= 0) {
                            acks.add(h.courier().agv().lastOrderAcknowledgedNanos());
                        }
                    });
            double wall = (System.nanoTime() - t0) / 1e9;
            double simulated = agv.hospital().clock().orElseThrow().call(s -> s.time()) - sim0;
            return new Delivery(run.outcome() == RefArcRun.Outcome.COMPLETED, simulated, wall, plan, agv.statesSent() - states0,
                    acks);
        }
    }

    private static void print(String path, List<Delivery> ds) {
        double sim = median(ds.stream().map(Delivery::simSeconds).toList());
        double wall = median(ds.stream().map(Delivery::wallSeconds).toList());
        double rate = median(ds.stream().map(d -> d.states() / d.wallSeconds()).toList());
        List<Double> acks = ds.stream().flatMap(d -> d.ackNanos().stream()).map(n -> n / 1e6).sorted().toList();
        boolean all = ds.stream().allMatch(Delivery::completed);
        System.out.printf(Locale.ROOT, "%-34s %8.1f %9.3f %8.0fx %9d %10s %9s %9s%s%n", path, sim, wall, sim / wall, ds.get(0).plan().size(),
                ds.get(0).states() == 0 ? "-" : String.format(Locale.ROOT, "%.1f", rate),
                acks.isEmpty() ? "-" : String.format(Locale.ROOT, "%.2f ms", percentile(acks, 50)),
                acks.isEmpty() ? "-" : String.format(Locale.ROOT, "%.2f ms", percentile(acks, 99)), all ? "" : "  (NOT ALL COMPLETED)");
    }

    /**
     * One building with N robots in one separate JVM (HospitalAgvMain --count N --speed S), one master here, one broker:
     * each robot patrols three rooms (rooms in turn, so robots meet in corridors and doors).
     */
    private static void fleet(MosquittoBroker broker, int n, String speed, Path dir) throws Exception {
        Files.createDirectories(dir);
        Path out = dir.resolve("fleet-robots.log");
        List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", System.getProperty("java.class.path"),
                HospitalAgvMain.class.getName(), "--broker", broker.url(), "--count", Integer.toString(n), "--speed", speed);
        Process robotsProcess = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        try (MasterControl master = MasterControl.connect(broker.url(), VdaTimeouts.defaults(), line -> { })) {
            List<VdaHospital> hs = new ArrayList<>();
            for (int i = 1; i <= n; i++) {
                VdaHospital h = new VdaHospital(master, "courier-" + i);
                // the broker keeps a previous run's retained OFFLINE (persistence on), after which awaitOnline only waits
                // the reconnect grace: a building of 20 robots may take longer to start on a loaded machine
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
                while (!h.courier().agv().awaitOnline()) {
                    if (System.nanoTime() > deadline) {
                        throw new IllegalStateException("courier-" + i + " did not come online: " + Files.readString(out));
                    }
                }
                hs.add(h);
            }
            double brokerCpu0 = cpuSeconds(broker.pid());
            double robotsCpu0 = cpuSeconds(robotsProcess.pid());
            double masterCpu0 = ownCpuSeconds();
            long t0 = System.nanoTime();
            ExecutorService pool = Executors.newFixedThreadPool(n);
            List<Future<double[]>> fs = new ArrayList<>();
            List<String> rooms = List.of("storage", "xray", "ward1", "ward2", "ward3");
            for (int i = 0; i < hs.size(); i++) {
                VdaHospital h = hs.get(i);
                Patrol patrol = new Patrol(h.objects().room(rooms.get(i % 5)), h.objects().room(rooms.get((i + 1) % 5)),
                        h.objects().room(rooms.get((i + 2) % 5)));
                fs.add(pool.submit(() -> {
                    long s = System.nanoTime();
                    RefArcRun run = h.run(patrol, st -> { });
                    return new double[] { run.outcome() == RefArcRun.Outcome.COMPLETED ? 1 : 0, (System.nanoTime() - s) / 1e9 };
                }));
            }
            List<Double> walls = new ArrayList<>();
            int completed = 0;
            for (Future<double[]> f : fs) {
                double[] r = f.get();
                completed += (int) r[0];
                walls.add(r[1]);
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            pool.shutdown();
            double brokerCpu = cpuSeconds(broker.pid()) - brokerCpu0;
            double robotsCpu = cpuSeconds(robotsProcess.pid()) - robotsCpu0;
            double masterCpu = ownCpuSeconds() - masterCpu0;
            robotsProcess.destroy();
            robotsProcess.waitFor(30, TimeUnit.SECONDS);
            String log = Files.readString(out);
            Matcher building = Pattern.compile("building: ([0-9.]+) s simulated in ([0-9.]+) s \\(([0-9.]+)x real time\\), CPU ([0-9.]+) s").matcher(log);
            long contacts = log.lines().filter(l -> l.startsWith("contact ")).count();
            System.out.printf(Locale.ROOT, "%n%d robots in one building on one broker (building in one JVM at --speed %s, master in another), each patrolling 3 rooms:%n",
                    n, speed);
            System.out.printf(Locale.ROOT, "  completed %d of %d (the others aborted with a reason); task wall time median %.2f s, max %.2f s; %d contacts%n",
                    completed, n, median(walls), Collections.max(walls), contacts);
            System.out.println(building.find() ? String.format(Locale.ROOT,
                    "  building clock: %s s simulated in %s s wall -> %sx real time (simulated/real); building CPU %s s", building.group(1),
                    building.group(2), building.group(3), building.group(4)) : "  (no building line in " + out + ")");
            double total = brokerCpu + robotsCpu + masterCpu;
            System.out.printf(Locale.ROOT, "  CPU over %.2f s wall: broker %.2f s (%.0f%%), robots %.2f s (%.0f%%), master %.2f s (%.0f%%); %.2f of 2 cores busy%n",
                    wall, brokerCpu, 100 * brokerCpu / total, robotsCpu, 100 * robotsCpu / total, masterCpu, 100 * masterCpu / total, total / wall);
        } finally {
            robotsProcess.destroy();
            robotsProcess.waitFor(20, TimeUnit.SECONDS);
            robotsProcess.destroyForcibly();
        }
    }

    /** utime + stime of a process from /proc, in seconds (clock ticks of 10 ms). */
    private static double cpuSeconds(long pid) throws IOException {
        String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        return (Long.parseLong(f[11]) + Long.parseLong(f[12])) / 100.0;
    }

    private static double ownCpuSeconds() {
        return ProcessHandle.current().info().totalCpuDuration().orElse(Duration.ZERO).toNanos() / 1e9;
    }

    private static double median(List<Double> xs) {
        return percentile(xs.stream().sorted().toList(), 50);
    }

    private static double percentile(List<Double> sorted, double p) {
        List<Double> s = sorted.stream().sorted().toList();
        int i = (int) Math.ceil(p / 100 * s.size()) - 1;
        return s.get(Math.max(0, Math.min(s.size() - 1, i)));
    }
}
