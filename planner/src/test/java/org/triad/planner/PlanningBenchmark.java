package org.triad.planner;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Benchmark main (not a test): hospital and IPC problems, warm JVM, medians. Ground ms is a full
 * grounding by a fresh planner; search ms (wall) and search CPU ms (this thread's CPU time, less
 * sensitive to other load on the machine) are a second call on the warm cache, i.e. what a later
 * goal with the same statics costs. Problems slower than 10 s are run once.
 * Run from the repository root:
 * {@code mvn -B -q -pl runtime test-compile && java -Xmx256m -cp runtime/target/classes:runtime/target/test-classes org.triad.planner.PlanningBenchmark ../shared/benchmarks/planning}
 * Without arguments the benchmarks are found beside the repository root ({@code ../shared}).
 * Optional second argument: a substring filter on problem paths.
 */
public final class PlanningBenchmark {
    private static final int RUNS = 5;
    private static final Duration TIMEOUT = Duration.ofSeconds(60);

    public static void main(String[] args) throws Exception {
        Path root = args.length > 0 ? Path.of(args[0]) : sharedBenchmarks();
        if (!Files.isDirectory(root.resolve("hospital")) || !Files.isDirectory(root.resolve("ipc"))) {
            System.err.println("error: no planning benchmarks (hospital/, ipc/) under " + root.toAbsolutePath().normalize());
            System.exit(2);
        }
        String filter = args.length > 1 ? args[1] : "";
        Map<String, Integer> optimal = new HashMap<>();
        for (String line : Files.readAllLines(root.resolve("hospital/optimal.tsv"))) {
            String[] c = line.split("\t");
            if (c[0].equals("N")) continue;
            optimal.put("p-" + c[0] + "-" + c[5] + ".pddl", Integer.parseInt(c[6]));
        }
        List<Path[]> jobs = new ArrayList<>();
        for (String n : List.of("10", "50", "100", "200", "500", "1000", "2000")) {
            for (String v : List.of("a", "b", "c")) {
                jobs.add(new Path[] {root.resolve("hospital/domain.pddl"), root.resolve("hospital/p-" + n + "-" + v + ".pddl")});
            }
        }
        try (Stream<Path> dirs = Files.list(root.resolve("ipc"))) {
            for (Path dir : dirs.filter(Files::isDirectory).sorted().toList()) {
                try (Stream<Path> files = Files.list(dir)) {
                    for (Path p : files.sorted().toList()) {
                        String f = p.getFileName().toString();
                        if (f.equals("domain.pddl") || f.endsWith("-domain.pddl")) continue;
                        Path d = dir.resolve("domain.pddl");
                        Path own = dir.resolve(f.replace(".pddl", "-domain.pddl"));
                        if (Files.exists(own)) d = own;
                        jobs.add(new Path[] {d, p});
                    }
                }
            }
        }
        System.out.printf("Java %s, max heap %d MB, %d runs (median), timeout %ds, %d cores, load average at start %.1f%n",
                System.getProperty("java.version"), Runtime.getRuntime().maxMemory() >> 20, RUNS, TIMEOUT.toSeconds(),
                Runtime.getRuntime().availableProcessors(), ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        System.out.println("| problem | ground ms | search ms | total ms | search CPU ms | length | optimal | status | validated | expanded | evaluated | peak heap MB |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (Path[] job : jobs) {
            String name = root.relativize(job[1]).toString();
            if (!name.contains(filter)) continue;
            Domain domain = PddlParser.parseDomain(job[0]);
            Problem problem = PddlParser.parseProblem(job[1]);
            System.gc();
            for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) pool.resetPeakUsage();
            double[] ground = new double[RUNS];
            double[] search = new double[RUNS];
            double[] searchCpu = new double[RUNS];
            SolveResult last = null;
            int runs = 0;
            for (int i = 0; i < RUNS + 1; i++) {
                // fresh planner: grounding is measured each time; then the same query on the warm cache
                TriadEngine planner = new TriadEngine();
                long t0 = System.nanoTime();
                SolveResult first = planner.solve(domain, problem, TIMEOUT);
                double total = (System.nanoTime() - t0) / 1e6;
                last = first;
                if (first.status() != SolveResult.Status.SOLVED || total > 10_000) {
                    ground[0] = first.stats().groundMillis();
                    search[0] = first.stats().searchMillis();
                    searchCpu[0] = Double.NaN;
                    runs = 1;
                    break;
                }
                if (i == 0) continue; // warm-up
                long c0 = ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
                SolveResult again = planner.solve(domain, problem, TIMEOUT);
                searchCpu[runs] = (ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime() - c0) / 1e6;
                ground[runs] = first.stats().groundMillis();
                search[runs] = again.stats().searchMillis();
                runs++;
            }
            long peak = 0;
            for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
                if (pool.getType() == MemoryType.HEAP) peak += pool.getPeakUsage().getUsed();
            }
            String validated = "-";
            String length = "-";
            if (last.isSolved()) {
                validated = PlanValidator.validate(domain, problem, last.plan()).valid() ? "yes" : "NO";
                length = Integer.toString(last.plan().length());
            }
            Integer opt = optimal.get(job[1].getFileName().toString());
            double g = median(ground, runs);
            double s = median(search, runs);
            double cpu = median(searchCpu, runs);
            System.out.printf("| %s | %.1f | %.1f | %.1f | %s | %s | %s | %s | %s | %d | %d | %d |%n", name, g, s, g + s,
                    Double.isNaN(cpu) ? "-" : String.format("%.1f", cpu), length,
                    opt == null || !name.startsWith("hospital") ? "-" : opt.toString(), last.status(), validated,
                    last.stats().expanded(), last.stats().evaluated(), peak >> 20);
        }
    }

    /**
     * {@code shared/benchmarks/planning} beside the repository root: the root is the nearest
     * directory at or above the working directory whose pom.xml is triad-parent's.
     */
    static Path sharedBenchmarks() throws java.io.IOException {
        for (Path d = Path.of(System.getProperty("user.dir")).toAbsolutePath(); d != null; d = d.getParent()) {
            Path pom = d.resolve("pom.xml");
            // a module's pom names triad-parent in its <parent> section: look at the project's own id
            if (Files.isRegularFile(pom)
                    && Files.readString(pom).replaceAll("(?s)<parent>.*?</parent>", "").contains("<artifactId>triad-parent</artifactId>")) {
                Path parent = d.getParent();
                return (parent == null ? d : parent).resolve("shared/benchmarks/planning");
            }
        }
        return Path.of("../shared/benchmarks/planning");
    }

    private static double median(double[] xs, int n) {
        double[] c = Arrays.copyOf(xs, n);
        Arrays.sort(c);
        return n % 2 == 1 ? c[n / 2] : (c[n / 2 - 1] + c[n / 2]) / 2;
    }
}
