package org.triad.tests.service;

import java.lang.management.ManagementFactory;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.triad.service.AccessTokens;
import org.triad.service.TriadService;
import org.triad.service.Views;
import org.triad.service.store.TaskState;

/**
 * Benchmark main (not a test) of {@code triad serve} on the hospital: (1) API throughput, task
 * submissions per second and their latency from concurrent HTTP clients, with the robots offline so
 * that only the API and the database work; (2) 1,000 queued tasks drained by 10 simulated couriers
 * running as fast as the machine allows ({@code sim:10@max}): drain time, dispatch time per task,
 * simulated seconds, heap. Arguments: {@code [submissions=2000] [clients=4] [tasks=1000] [robots=10]}.
 * See service/BENCHMARK.md.
 */
public final class ServiceBenchmark {
    private static final String TOKEN = "benchmark-submit-token";
    private static final String OPERATOR = "benchmark-operator-token";
    private static final List<String> ROOMS = List.of("storage", "xray", "ward1", "ward2", "ward3", "lobby");
    private static final List<String> ITEMS = List.of("gauze", "syringe", "bandage");

    private ServiceBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int submissions = args.length > 0 ? Integer.parseInt(args[0]) : 2000;
        int clients = args.length > 1 ? Integer.parseInt(args[1]) : 4;
        int tasks = args.length > 2 ? Integer.parseInt(args[2]) : 1000;
        int robots = args.length > 3 ? Integer.parseInt(args[3]) : 10;
        Path hospital = Path.of(args.length > 4 ? args[4] : "models/hospital/src/main/models");
        Path dir = Files.createTempDirectory("triad-service-benchmark");
        System.out.printf(Locale.ROOT, "triad serve benchmark: %d cores, max heap %d MB, Java %s%n", Runtime.getRuntime().availableProcessors(),
                Runtime.getRuntime().maxMemory() >> 20, System.getProperty("java.version"));
        throughput(hospital, dir.resolve("api"), submissions, clients);
        drain(hospital, dir.resolve("fleet"), tasks, robots);
    }

    private static TriadService start(Path hospital, Path db, String robots) {
        return TriadService.start(new TriadService.Options(hospital, List.of(robots), null, db, null, "127.0.0.1", 0,
                Map.of(AccessTokens.SUBMIT_ENV, TOKEN, AccessTokens.OPERATOR_ENV, OPERATOR)));
    }

    private static String task(int i) {
        return i % 3 == 2 ? "{\"task\": \"Deliver\", \"args\": {\"i\": \"" + ITEMS.get(i % ITEMS.size()) + "\", \"to\": \"" + ROOMS.get((i / 3) % ROOMS.size()) + "\"}}"
                : "{\"task\": \"GoTo\", \"args\": {\"dst\": \"" + ROOMS.get((i * 5 + i / 6) % ROOMS.size()) + "\"}}";
    }

    private static void throughput(Path hospital, Path db, int n, int clients) throws Exception {
        try (TriadService s = start(hospital, db, "dry:1")) {
            s.fleet().setOnline("dry-1", false);
            HttpClient http = HttpClient.newHttpClient();
            URI uri = URI.create(s.url() + "/api/tasks");
            for (int i = 0; i < 200; i++) { // warm-up
                post(http, uri, task(i));
            }
            long[] latencies = new long[n];
            ExecutorService pool = Executors.newFixedThreadPool(clients);
            long start = System.nanoTime();
            List<Future<?>> done = new ArrayList<>();
            for (int c = 0; c < clients; c++) {
                int client = c;
                done.add(pool.submit(() -> {
                    for (int i = client; i < n; i += clients) {
                        long t0 = System.nanoTime();
                        post(http, uri, task(i));
                        latencies[i] = System.nanoTime() - t0;
                    }
                    return null;
                }));
            }
            for (Future<?> f : done) {
                f.get();
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            pool.shutdown();
            Arrays.sort(latencies);
            System.out.println();
            System.out.println("| API throughput | value |");
            System.out.println("|---|---|");
            System.out.printf(Locale.ROOT, "| submissions (POST /api/tasks, %d clients) | %d |%n", clients, n);
            System.out.printf(Locale.ROOT, "| submissions/s | %.0f |%n", n / seconds);
            System.out.printf(Locale.ROOT, "| latency p50 | %.2f ms |%n", latencies[n / 2] / 1e6);
            System.out.printf(Locale.ROOT, "| latency p99 | %.2f ms |%n", latencies[(int) (n * 0.99)] / 1e6);
            System.out.printf(Locale.ROOT, "| tasks stored and queued | %d |%n", s.fleet().tasks(TaskState.QUEUED, Integer.MAX_VALUE).size());
        }
    }

    private static void post(HttpClient http, URI uri, String body) throws Exception {
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(uri).header("Authorization", "Bearer " + TOKEN)
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
        if (r.statusCode() != 201) {
            throw new IllegalStateException(r.statusCode() + " " + r.body());
        }
    }

    private static void drain(Path hospital, Path db, int n, int robots) throws Exception {
        try (TriadService s = start(hospital, db, "sim:" + robots + "@max")) {
            List<String> names = s.fleet().robots().stream().map(Views.RobotView::name).toList();
            names.forEach(r -> s.fleet().setOnline(r, false));
            for (int i = 0; i < n; i++) {
                s.fleet().submit(new com.fasterxml.jackson.databind.ObjectMapper().readTree(task(i)));
            }
            long heapBefore = usedHeap();
            long start = System.nanoTime();
            names.forEach(r -> s.fleet().setOnline(r, true));
            long peakHeap = 0;
            while (!s.fleet().tasks(TaskState.QUEUED, 1).isEmpty() || !s.fleet().tasks(TaskState.RUNNING, 1).isEmpty()) {
                Thread.sleep(200);
                peakHeap = Math.max(peakHeap, Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory());
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            int completed = s.fleet().tasks(TaskState.COMPLETED, Integer.MAX_VALUE).size();
            int aborted = s.fleet().tasks(TaskState.ABORTED, Integer.MAX_VALUE).size();
            long[] dispatch = s.fleet().dispatchStatistics();
            double simSeconds = 0;
            for (String r : names) {
                simSeconds += s.fleet().floor(r).map(m -> m.time()).orElse(0.0);
            }
            long heapAfter = usedHeap();
            System.out.println();
            System.out.printf(Locale.ROOT, "| %d queued tasks on %d simulated couriers (sim:%d@max) | value |%n", n, robots, robots);
            System.out.println("|---|---|");
            System.out.printf(Locale.ROOT, "| drain time | %.1f s |%n", seconds);
            System.out.printf(Locale.ROOT, "| tasks completed / aborted | %d / %d |%n", completed, aborted);
            System.out.printf(Locale.ROOT, "| tasks/s | %.1f |%n", n / seconds);
            System.out.printf(Locale.ROOT, "| dispatch time per task (mean, incl. one first-goal plan per idle robot) | %.2f ms over %d dispatches |%n",
                    dispatch[0] / 1e6, dispatch[1]);
            System.out.printf(Locale.ROOT, "| simulated time, all robots | %.0f s (%.1fx wall clock) |%n", simSeconds, simSeconds / seconds);
            System.out.printf(Locale.ROOT, "| heap used after GC: queued / drained | %d MB / %d MB |%n", heapBefore >> 20, heapAfter >> 20);
            System.out.printf(Locale.ROOT, "| heap in use, peak sampled | %d MB |%n", peakHeap >> 20);
            System.out.printf(Locale.ROOT, "| process CPU time | %.1f s |%n", cpuSeconds());
        }
    }

    private static long usedHeap() {
        System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    private static double cpuSeconds() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os) {
            return os.getProcessCpuTime() / 1e9;
        }
        return Double.NaN;
    }
}
