package org.triad.service;

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
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The fault script of issue #26, a main (not a test): prints three tables.
 * (1) N tasks submitted at full speed by 4 clients while the service process is killed with SIGKILL
 * at K random moments and restarted each time, on the embedded default and on PostgreSQL:
 * tasks stored (each submission carries an Idempotency-Key, so a retry after a lost answer stores
 * nothing new: stored = acknowledged), acknowledged tasks lost, duplicated (completed twice, or an id
 * given twice), stuck (not completed two minutes after the last start), starts that failed, time to
 * recover (process start to serving).
 * (2) Fail-over on PostgreSQL: two instances, the dispatching one killed with a task in flight F times:
 * take-over time (kill to the other's {@code /api/health} saying it dispatches), median and max.
 * (3) Submissions/s and p99 on both, one process each, robots offline.
 * Arguments: {@code [tasks=500] [kills=20] [failovers=10] [submissions=2000]} (kills and failovers 0: only the last table).
 */
public final class QueueFaultBenchmark {
    private static final String[] ROOMS = { "xray", "ward1", "ward2", "storage" };

    private QueueFaultBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        int tasks = args.length > 0 ? Integer.parseInt(args[0]) : 500;
        int kills = args.length > 1 ? Integer.parseInt(args[1]) : 20;
        int failovers = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        int submissions = args.length > 3 ? Integer.parseInt(args[3]) : 2000;
        System.out.printf(Locale.ROOT, "queue fault benchmark: %d cores, Java %s, load average %.1f%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"), java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        Path dir = Files.createTempDirectory("triad-queue-faults");
        if (kills > 0 || failovers > 0) {
            faults(dir, tasks, kills, failovers);
        }
        try (PostgresServer pg = PostgresServer.start()) {
            System.out.println();
            System.out.printf(Locale.ROOT, "| %d submissions, 4 clients | submissions/s | p50 | p99 |%n", submissions);
            System.out.println("|---|---|---|---|");
            throughput("embedded (SQLite, WAL, synchronous=FULL)", dir.resolve("throughput").toString(), submissions);
            throughput("PostgreSQL (synchronous_commit=on)", pg.url(), submissions);
        }
    }

    private static void faults(Path dir, int tasks, int kills, int failovers) throws Exception {
        try (PostgresServer pg = PostgresServer.start()) {
            System.out.println();
            System.out.printf(Locale.ROOT, "| %d tasks at full speed, %d SIGKILLs | acknowledged | stored | lost | duplicated | stuck | failed starts | recovery median | recovery max |%n",
                    tasks, kills);
            System.out.println("|---|---|---|---|---|---|---|---|---|");
            if (kills > 0) {
                kills("embedded (SQLite, WAL, synchronous=FULL)", dir.resolve("kills").toString(), tasks, kills);
                kills("PostgreSQL 1 instance", pg.url(), tasks, kills);
            }
            if (failovers > 0) {
                failover(pg, failovers);
            }
        }
    }

    private static String body(int i) {
        return "{\"dst\": \"" + ROOMS[i % ROOMS.length] + "\"}";
    }

    private static void kills(String name, String db, int tasks, int kills) throws Exception {
        Map<Long, String> acknowledged = new ConcurrentHashMap<>();
        AtomicInteger duplicateIds = new AtomicInteger();
        List<Long> recoveries = new ArrayList<>();
        int failedStarts = 0;
        Random random = new Random(26);
        try (ServiceProcesses processes = new ServiceProcesses()) {
            AtomicInteger next = new AtomicInteger();
            String[] url = new String[1];
            AtomicBoolean done = new AtomicBoolean();
            ExecutorService clients = Executors.newFixedThreadPool(4);
            List<Future<?>> running = new ArrayList<>();
            long t0 = System.nanoTime();
            ServiceProcesses.Running service = processes.startOrFail(db, "dry:4,state=Morning");
            recoveries.add((System.nanoTime() - t0) / 1_000_000);
            url[0] = service.url();
            for (int c = 0; c < 4; c++) {
                running.add(clients.submit(() -> {
                    for (int i = next.getAndIncrement(); i < tasks; i = next.getAndIncrement()) {
                        while (true) {
                            // the key makes a retry after a lost answer find the task stored the first time
                            ServiceFixture.Response r = processes.submit(url[0], "GoTo", body(i), name.hashCode() + "-" + i);
                            if (r.status() == 201 || r.status() == 200) {
                                if (acknowledged.putIfAbsent(r.body().get("id").asLong(), ROOMS[i % ROOMS.length]) != null && r.status() == 201) {
                                    duplicateIds.incrementAndGet();
                                }
                                break;
                            }
                            ServiceFixture.sleep(20);
                        }
                    }
                    return null;
                }));
            }
            for (int k = 0; k < kills; k++) {
                ServiceFixture.sleep(100 + random.nextInt(900));
                service.kill();
                long start = System.nanoTime();
                ServiceProcesses.Start s = processes.start(db, "dry:4,state=Morning");
                while (s.running() == null) {
                    failedStarts++;
                    System.err.println(name + ": a start failed: " + s.error());
                    s = processes.start(db, "dry:4,state=Morning");
                }
                recoveries.add((System.nanoTime() - start) / 1_000_000);
                service = s.running();
                url[0] = service.url();
            }
            for (Future<?> f : running) {
                f.get();
            }
            done.set(true);
            clients.shutdown();
            int lost = 0;
            int duplicated = duplicateIds.get();
            int stuck = 0;
            long deadline = System.nanoTime() + 120_000_000_000L;
            for (Map.Entry<Long, String> e : acknowledged.entrySet()) {
                JsonNode t = processes.get(url[0], "/api/tasks/" + e.getKey()).body();
                if (t == null || !t.has("args") || !e.getValue().equals(t.get("args").get("dst").asText())) {
                    lost++;
                    continue;
                }
                while (!t.get("state").asText().equals("completed") && System.nanoTime() < deadline) {
                    ServiceFixture.sleep(50);
                    t = processes.get(url[0], "/api/tasks/" + e.getKey()).body();
                }
                if (!t.get("state").asText().equals("completed")) {
                    stuck++;
                } else if (PostgresFailoverTest.kinds(t).stream().filter("task_completed"::equals).count() != 1) {
                    duplicated++;
                }
            }
            long[] r = recoveries.stream().mapToLong(Long::longValue).sorted().toArray();
            int stored = processes.get(url[0], "/api/tasks").body().size();
            System.out.printf(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %d | %.2f s | %.2f s |%n", name, acknowledged.size(), stored, lost, duplicated, stuck,
                    failedStarts, r[r.length / 2] / 1000.0, r[r.length - 1] / 1000.0);
        }
    }

    private static void failover(PostgresServer pg, int times) throws Exception {
        List<Long> takeovers = new ArrayList<>();
        List<Long> ids = new ArrayList<>();
        try (ServiceProcesses processes = new ServiceProcesses()) {
            String robots = "dry:1,state=Morning,delay=100";
            ServiceProcesses.Running active = processes.startOrFail(pg.url(), robots);
            ServiceProcesses.Running standby = processes.startOrFail(pg.url(), robots);
            for (int i = 0; i < times; i++) {
                long id = processes.submit(standby.url(), "Patrol", "{\"a\": \"ward2\", \"b\": \"storage\", \"c\": \"ward1\"}").body().get("id").asLong();
                ids.add(id);
                JsonNode t = processes.get(standby.url(), "/api/tasks/" + id).body();
                while (!PostgresFailoverTest.kinds(t).contains("action_succeeded")) {
                    ServiceFixture.sleep(20);
                    t = processes.get(standby.url(), "/api/tasks/" + id).body();
                }
                active.kill();
                long killed = System.nanoTime();
                while (!processes.get(standby.url(), "/api/health").body().get("dispatching").asBoolean()) {
                    ServiceFixture.sleep(10);
                }
                takeovers.add((System.nanoTime() - killed) / 1_000_000);
                active = standby;
                standby = processes.startOrFail(pg.url(), robots);
            }
            int lost = 0;
            int twice = 0;
            long deadline = System.nanoTime() + 120_000_000_000L;
            for (long id : ids) {
                JsonNode t = processes.get(active.url(), "/api/tasks/" + id).body();
                while (t != null && !t.get("state").asText().equals("completed") && System.nanoTime() < deadline) {
                    ServiceFixture.sleep(50);
                    t = processes.get(active.url(), "/api/tasks/" + id).body();
                }
                if (t == null || !t.get("state").asText().equals("completed")) {
                    lost++;
                } else if (PostgresFailoverTest.kinds(t).stream().filter("task_completed"::equals).count() != 1) {
                    twice++;
                }
            }
            long[] r = takeovers.stream().mapToLong(Long::longValue).sorted().toArray();
            System.out.println();
            System.out.println("| fail-over on PostgreSQL, 2 instances | value |");
            System.out.println("|---|---|");
            System.out.printf(Locale.ROOT, "| dispatcher killed mid-task | %d times |%n", times);
            System.out.printf(Locale.ROOT, "| take-over time median / max | %.2f s / %.2f s |%n", r[r.length / 2] / 1000.0, r[r.length - 1] / 1000.0);
            System.out.printf(Locale.ROOT, "| tasks in flight lost (not completed) / completed twice | %d / %d |%n", lost, twice);
        }
    }

    private static void throughput(String name, String db, int n) throws Exception {
        try (ServiceProcesses processes = new ServiceProcesses()) {
            ServiceProcesses.Running s = processes.startOrFail(db, "dry:1,state=Morning");
            HttpClient http = HttpClient.newHttpClient();
            http.send(HttpRequest.newBuilder(URI.create(s.url() + "/api/robots/dry-1/offline")).header("Authorization", "Bearer " + ServiceFixture.OPERATOR)
                    .POST(HttpRequest.BodyPublishers.noBody()).build(), HttpResponse.BodyHandlers.ofString());
            for (int i = 0; i < 200; i++) {
                processes.submit(s.url(), "GoTo", body(i));
            }
            long[] latencies = new long[n];
            ExecutorService pool = Executors.newFixedThreadPool(4);
            List<Future<?>> done = new ArrayList<>();
            long start = System.nanoTime();
            for (int c = 0; c < 4; c++) {
                int client = c;
                done.add(pool.submit(() -> {
                    for (int i = client; i < n; i += 4) {
                        long t0 = System.nanoTime();
                        if (processes.submit(s.url(), "GoTo", body(i)).status() != 201) {
                            throw new IllegalStateException("a submission failed");
                        }
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
            System.out.printf(Locale.ROOT, "| %s | %.0f | %.2f ms | %.2f ms |%n", name, n / seconds, latencies[n / 2] / 1e6, latencies[(int) (n * 0.99)] / 1e6);
        }
    }
}
