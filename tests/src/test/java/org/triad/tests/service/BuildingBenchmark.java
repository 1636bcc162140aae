package org.triad.tests.service;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;

import org.triad.examples.hospital.vda5050.HospitalAgvMain;
import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.service.Views.TaskView;
import org.triad.vda5050.broker.MosquittoBroker;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Benchmark main (not a test): one building process with N simulated couriers ({@code HospitalAgvMain
 * --count N}, its own JVM) on a real Mosquitto, the service (this JVM) driving them over VDA 5050, and T
 * mixed tasks (deliveries, guides, patrols, trips) submitted at once. Prints how each ended (completed, or
 * aborted/refused with the reasons), picks per item against completed deliveries (an object delivered
 * twice would show as more picks than deliveries), tasks per simulated hour, the dispatcher's time per
 * dispatch (median, p99), the CPU seconds of broker, building and service, the orders the couriers accepted, the
 * contact lines of the building's log, where the robots' and the tasks' time went ({@link TaskTimeSplit}) and the
 * building's own clock as it stops (whether it kept the speed asked for). Arguments:
 * {@code [robots=10] [tasks=200] [speed=10] [mix=all|moves] [models=models/hospital/src/main/models] [minutes=30]} ({@code moves}: patrols and
 * trips only, for couriers that each have a simulation of their own, where items and people are not shared); see service/BENCHMARK.md.
 * It stops waiting when every robot is out of dispatch (3 aborts in a row each), or after {@code minutes} of wall time
 * (a fleet that jams does neither), and reports the rest as queued or running.
 */
public final class BuildingBenchmark {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final List<String> ROOMS = List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby");
    private static final List<String> ITEMS = List.of("gauze", "syringe", "bandage");
    private static final List<String> PEOPLE = List.of("alice", "bob");

    private BuildingBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int robots = args.length > 0 ? Integer.parseInt(args[0]) : 10;
        int tasks = args.length > 1 ? Integer.parseInt(args[1]) : 200;
        double speed = args.length > 2 ? Double.parseDouble(args[2]) : 10;
        boolean movesOnly = args.length > 3 && args[3].equals("moves");
        Path models = Path.of(args.length > 4 ? args[4] : "models/hospital/src/main/models");
        long minutes = args.length > 5 ? Long.parseLong(args[5]) : 30;
        Path dir = Files.createTempDirectory("triad-building-benchmark");
        System.out.printf(Locale.ROOT, "building benchmark: %d robots, %d tasks, %.0fx real time; %d cores, Java %s%n", robots, tasks, speed,
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"));
        Process building = null;
        int[] endedCompleted = { -1, -1 };
        try (MosquittoBroker broker = MosquittoBroker.start(dir.resolve("broker"))) {
            Path log = dir.resolve("building.log");
            building = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx1g", "-cp",
                    System.getProperty("java.class.path"), HospitalAgvMain.class.getName(), "--broker", broker.url(), "--count",
                    Integer.toString(robots), "--speed", Double.toString(speed)).redirectErrorStream(true).redirectOutput(log.toFile()).start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (Files.readString(log).split("ONLINE", -1).length - 1 < robots) {
                if (!building.isAlive() || System.nanoTime() > deadline) {
                    throw new IllegalStateException("the building did not come up: " + Files.readString(log));
                }
                Thread.sleep(100);
            }
            // traffic control's wait bound runs on the wall clock: 120 simulated s is 120 / speed wall s (the default, 120 wall
            // s, was 20 simulated minutes at 10x, so a task whose drives kept timing out took hours of simulated time to end)
            String spec = String.format(Locale.ROOT, "vda5050:%s,wait=30,traffic=%.1f", broker.url(), 120 / speed);
            try (TriadService s = TriadService.start(new TriadService.Options(models, List.of(spec), null,
                    dir.resolve("db"), null, "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, "bench-submit", AccessTokens.OPERATOR_ENV, "bench-operator")))) {
                System.out.printf(Locale.ROOT, "fleet: %d robots joined%n", s.fleet().robots().size());
                double[] cpu0 = { cpuSeconds(broker.pid()), cpuSeconds(building.pid()), cpuSeconds(ProcessHandle.current().pid()) };
                long t0 = System.nanoTime();
                Map<String, String> itemAt = new HashMap<>();
                ITEMS.forEach(i -> itemAt.put(i, "storage"));
                List<Long> ids = new ArrayList<>();
                for (int i = 0; i < tasks; i++) {
                    ids.add(s.fleet().submit(task(movesOnly ? 2 + i % 2 : i, itemAt)).id());
                }
                Map<Long, TaskView> ended = new TreeMap<>();
                TaskTimeSplit split = new TaskTimeSplit();
                long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(minutes);
                while (ended.size() < ids.size() && System.nanoTime() < end) {
                    for (long id : ids) {
                        if (!ended.containsKey(id)) {
                            TaskView t = s.fleet().task(id).orElseThrow();
                            if (Set.of("completed", "aborted", "refused", "cancelled", "done").contains(t.state())) {
                                ended.put(id, t);
                            }
                        }
                    }
                    if (s.fleet().robots().stream().noneMatch(r -> r.online() || r.task() != null)) {
                        System.out.println("every robot is out of dispatch; the rest stays queued");
                        break;
                    }
                    split.sample(s.fleet().robots(), s.traffic().longerThan(0));
                    Thread.sleep(200);
                }
                double wall = (System.nanoTime() - t0) / 1e9;
                double[] cpu = { cpuSeconds(broker.pid()) - cpu0[0], cpuSeconds(building.pid()) - cpu0[1],
                        cpuSeconds(ProcessHandle.current().pid()) - cpu0[2] };
                report(s, ids, ended, wall, speed, cpu, Files.readAllLines(log));
                endedCompleted[0] = ended.size();
                endedCompleted[1] = (int) ended.values().stream().filter(t -> t.state().equals("completed")).count();
                List<TaskView> all = new ArrayList<>();
                for (long id = 1; s.fleet().task(id).isPresent(); id++) {
                    all.add(s.fleet().task(id).orElseThrow()); // the service's own Recharge tasks too
                }
                split.print(all, speed);
            }
        } finally {
            if (building != null) {
                building.destroy();
                building.waitFor(30, TimeUnit.SECONDS);
                // the building's own clock, printed as it stops: whether it kept the speed asked for
                for (String l : Files.readAllLines(dir.resolve("building.log"))) {
                    java.util.regex.Matcher m = java.util.regex.Pattern.compile("^building: ([0-9.]+) s simulated in").matcher(l);
                    if (m.find()) {
                        double hours = Double.parseDouble(m.group(1)) / 3600;
                        System.out.println(l);
                        System.out.printf(Locale.ROOT, "by the building's clock: %.0f tasks ended, %.0f completed per simulated hour%n",
                                endedCompleted[0] / hours, endedCompleted[1] / hours);
                    }
                }
            }
        }
    }

    /** Deliveries (from where the generator last sent the item), guides, patrols and trips, in turn. */
    private static ObjectNode task(int i, Map<String, String> itemAt) {
        ObjectNode args = JSON.createObjectNode();
        String name;
        switch (i % 4) {
            case 0 -> {
                String item = ITEMS.get((i / 4) % ITEMS.size());
                String to = ROOMS.get((i / 4 + 2) % ROOMS.size());
                name = "CollectAndDeliver";
                args.put("i", item).put("from", itemAt.get(item)).put("to", to);
                itemAt.put(item, to);
            }
            case 1 -> {
                name = "Guide";
                args.put("p", PEOPLE.get((i / 4) % PEOPLE.size())).put("to", ROOMS.get((i / 4 + 1) % ROOMS.size()));
            }
            case 2 -> {
                name = "Patrol";
                args.put("a", ROOMS.get(i % 6)).put("b", ROOMS.get((i + 2) % 6)).put("c", ROOMS.get((i + 4) % 6));
            }
            default -> {
                name = "GoTo";
                args.put("dst", ROOMS.get((i / 4) % ROOMS.size()));
            }
        }
        return JSON.createObjectNode().put("task", name).set("args", args);
    }

    private static void report(TriadService s, List<Long> ids, Map<Long, TaskView> ended, double wall, double speed, double[] cpu, List<String> log) {
        Map<String, Integer> states = new TreeMap<>();
        Map<String, Integer> reasons = new TreeMap<>();
        Map<String, Integer> delivered = new TreeMap<>();
        for (TaskView t : ended.values()) {
            states.merge(t.state(), 1, Integer::sum);
            if (!t.state().equals("completed")) {
                reasons.merge(t.task() + ": " + (t.reason() == null ? "(no reason)" : t.reason().replaceAll("\\d+", "N")), 1, Integer::sum);
            } else if (t.task().equals("CollectAndDeliver")) {
                delivered.merge(t.args().path("i").asText(), 1, Integer::sum);
            }
        }
        Map<String, Integer> picks = new TreeMap<>();
        long orders = log.stream().filter(l -> l.contains(": accepted order ")).count();
        long contacts = log.stream().filter(l -> l.startsWith("contact")).count();
        for (String line : log) {
            for (String item : ITEMS) {
                if (line.contains(": accepted order ") && line.contains("[pick " + item + "]")) {
                    picks.merge(item, 1, Integer::sum);
                }
            }
        }
        List<Long> times = new ArrayList<>(s.fleet().dispatchTimes());
        times.sort(null);
        int completed = states.getOrDefault("completed", 0);
        states.put("queued (not ended)", ids.size() - ended.size());
        System.out.printf(Locale.ROOT, "%nended %d of %d in %.1f s wall (%.0f simulated s): %s%n", ended.size(), ids.size(), wall, wall * speed, states);
        reasons.forEach((r, n) -> System.out.printf(Locale.ROOT, "  %3d x %s%n", n, r));
        long requeues = 0;
        long requeued = 0;
        for (long id : ids) {
            long n = s.fleet().task(id).orElseThrow().events().stream().filter(e -> e.kind().equals("congestion_requeued")).count();
            requeues += n;
            requeued += n > 0 ? 1 : 0;
        }
        System.out.printf(Locale.ROOT, "queued again after congestion: %d times, %d tasks%n", requeues, requeued);
        System.out.printf(Locale.ROOT, "deliveries completed per item %s, picks accepted per item %s%n", delivered, picks);
        System.out.printf(Locale.ROOT, "orders the couriers accepted: %d; contact lines in the building's log: %d%n", orders, contacts);
        System.out.printf(Locale.ROOT, "tasks ended per simulated hour: %.0f%n", ended.size() / (wall * speed / 3600));
        System.out.printf(Locale.ROOT, "tasks completed per simulated hour: %.0f%n", completed / (wall * speed / 3600));
        if (!times.isEmpty()) {
            System.out.printf(Locale.ROOT, "dispatch (choosing the robot, estimates from each idle robot's state): %d dispatches, median %.2f ms, p99 %.2f ms%n",
                    times.size(), times.get(times.size() / 2) / 1e6, times.get(Math.min(times.size() - 1, (int) Math.ceil(times.size() * 0.99) - 1)) / 1e6);
        }
        double total = cpu[0] + cpu[1] + cpu[2];
        System.out.printf(Locale.ROOT, "CPU seconds: broker %.1f (%.0f %%), building %.1f (%.0f %%), service %.1f (%.0f %%)%n", cpu[0], 100 * cpu[0] / total,
                cpu[1], 100 * cpu[1] / total, cpu[2], 100 * cpu[2] / total);
    }

    /** User plus system CPU time of a process, seconds, from /proc (clock ticks of 1/100 s). */
    private static double cpuSeconds(long pid) {
        try {
            String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return (Long.parseLong(f[11]) + Long.parseLong(f[12])) / 100.0;
        } catch (Exception e) {
            return Double.NaN;
        }
    }
}
