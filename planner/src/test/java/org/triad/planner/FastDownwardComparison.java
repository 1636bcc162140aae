package org.triad.planner;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Benchmark main (not a test): Triad against Fast Downward's lama-first on IPC problems, each planner
 * as a whole process ({@code java ... SolveOnce} and {@code fast-downward.py --alias lama-first}),
 * one run each with a time cap, every plan replayed by {@link PlanValidator} on the lifted domain.
 * Prints a Markdown table. Reads only local files:
 * {@code FastDownwardComparison [--fd-cache DIR] FAST_DOWNWARD_PY TIMEOUT_S CORPUS_DIR DOMAIN_FOLDER/PROBLEM.pddl...}
 * (the domain file is found as Fast Downward's driver finds it). With {@code --fd-cache}, Fast
 * Downward runs once per problem: its plan and wall seconds are kept as {@code DIR/FOLDER/PROBLEM.pddl.plan}
 * and {@code .seconds} ("timeout" when it found none) and reused by later runs. The last line gives
 * the median length ratio over the problems both solved. With {@code --repeat N}, Triad runs N more
 * times idle and N times with a CPU load beside it (busy threads, twice the cores, in this JVM) and a
 * column gives the lengths of those runs ("all L" when every run gave L): the engine's budgets count
 * work, so they must all be the same. On a shared machine the idle runs are made as idle as the
 * machine allows: their process runs at {@code nice -n -10} (ahead of every other process; where
 * that is not permitted, {@code nice} says so and runs it at the usual priority), and the load
 * average at the start of each idle and loaded run is summed up at the end. The Triad CPU column is the CPU seconds of its whole process
 * (all threads, JIT and GC included), what wall seconds would be on an idle machine with one core
 * free for it. See planner/BENCHMARK.md.
 */
public final class FastDownwardComparison {
    public static void main(String[] args) throws Exception {
        Path fdCache = null;
        int repeat = 0;
        while (args.length > 1 && (args[0].equals("--fd-cache") || args[0].equals("--repeat"))) {
            if (args[0].equals("--fd-cache")) fdCache = Path.of(args[1]).toAbsolutePath();
            else repeat = Integer.parseInt(args[1]);
            args = java.util.Arrays.copyOfRange(args, 2, args.length);
        }
        if (args.length < 4) {
            System.err.println("usage: FastDownwardComparison [--fd-cache DIR] [--repeat N] FAST_DOWNWARD_PY TIMEOUT_S CORPUS_DIR FOLDER/PROBLEM.pddl...");
            System.exit(2);
        }
        List<Double> ratios = new ArrayList<>();
        List<Double> timeRatios = new ArrayList<>();
        List<Double> cpuRatios = new ArrayList<>();
        String fd = args[0];
        double timeout = Double.parseDouble(args[1]);
        Path root = Path.of(args[2]).toAbsolutePath();
        Path work = Files.createTempDirectory("triad-fd");
        System.out.printf("Java %s, %d cores, load average at start %.1f, cap %.0f s per planner and problem%n%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), timeout);
        String repeatHeader = repeat > 0 ? " Triad lengths, " + repeat + " idle / " + repeat + " loaded |" : "";
        System.out.println("| problem | Triad s | Triad CPU s | Triad length | Triad valid | FD s | FD length | FD valid | length ratio |" + repeatHeader);
        System.out.println("|---|---|---|---|---|---|---|---|---|" + (repeat > 0 ? "---|" : ""));
        int varying = 0;
        double[] idleLoad = {Double.MAX_VALUE, 0};
        double[] loadedLoad = {Double.MAX_VALUE, 0};
        List<String> notes = new ArrayList<>();
        for (int i = 3; i < args.length; i++) {
            Path problemFile = root.resolve(args[i]);
            Path domainFile = IpcCorpusCheck.domainOf(problemFile);
            Domain domain = null;
            Problem problem = null;
            try {
                domain = PddlParser.parseDomain(domainFile);
                problem = PddlParser.parseProblem(problemFile);
            } catch (org.triad.planner.pddl.PddlParseException e) {
                // Fast Downward still runs; its plan cannot be replayed on a domain Triad does not read
            }
            Path triadPlan = work.resolve("triad.plan");
            Path fdPlan = work.resolve("fd.plan");
            Files.deleteIfExists(triadPlan);
            Files.deleteIfExists(fdPlan);
            Path triadCpu = work.resolve("triad.plan.cpu");
            Files.deleteIfExists(triadCpu);
            String cp = String.join(java.io.File.pathSeparator, java.util.Arrays.stream(System.getProperty("java.class.path")
                    .split(java.io.File.pathSeparator)).map(e -> Path.of(e).toAbsolutePath().toString()).toList());
            double triadS = run(work, "triad.log", timeout, List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss4m", "-cp", cp,
                    SolveOnce.class.getName(), domainFile.toString(), problemFile.toString(), triadPlan.toString(), Double.toString(timeout)));
            Path cachedPlan = fdCache == null ? null : fdCache.resolve(args[i] + ".plan");
            Path cachedSeconds = fdCache == null ? null : fdCache.resolve(args[i] + ".seconds");
            double fdS;
            if (cachedSeconds != null && Files.exists(cachedSeconds)) {
                String text = Files.readString(cachedSeconds).trim();
                fdS = text.equals("timeout") ? Double.NaN : Double.parseDouble(text);
                if (Files.exists(cachedPlan)) Files.copy(cachedPlan, fdPlan);
            } else {
                fdS = run(work, "fd.log", timeout, List.of("python3", fd, "--alias", "lama-first", "--overall-time-limit", (int) timeout + "s",
                        "--plan-file", fdPlan.toString(), domainFile.toString(), problemFile.toString()));
                if (cachedSeconds != null) {
                    Files.createDirectories(cachedSeconds.getParent());
                    if (Files.exists(fdPlan)) Files.copy(fdPlan, cachedPlan, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                    Files.writeString(cachedSeconds, Files.exists(fdPlan) && !Double.isNaN(fdS) ? Double.toString(fdS) : "timeout");
                }
            }
            String[] t = check(domain, problem, triadPlan);
            String[] f = check(domain, problem, fdPlan);
            String ratio = t[0].equals("-") || f[0].equals("-") ? "-" : String.format("%.2f", Double.parseDouble(t[0]) / Double.parseDouble(f[0]));
            if (!ratio.equals("-")) ratios.add(Double.parseDouble(t[0]) / Double.parseDouble(f[0]));
            String cpu = Files.exists(triadCpu) ? String.format("%.2f", Double.parseDouble(Files.readString(triadCpu).trim())) : "-";
            String repeated = "";
            if (repeat > 0) {
                List<String> idle = new ArrayList<>();
                List<String> loaded = new ArrayList<>();
                List<String> solve = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss4m", "-cp", cp,
                        SolveOnce.class.getName(), domainFile.toString(), problemFile.toString(), triadPlan.toString(), Double.toString(timeout));
                List<String> idleSolve = new ArrayList<>(List.of("nice", "-n", "-10"));
                idleSolve.addAll(solve);
                for (int k = 0; k < 2 * repeat; k++) {
                    boolean withLoad = k >= repeat;
                    Files.deleteIfExists(triadPlan);
                    CpuLoad load = withLoad ? new CpuLoad(2 * Runtime.getRuntime().availableProcessors()) : null;
                    double loadAverage = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
                    (withLoad ? loadedLoad : idleLoad)[0] = Math.min((withLoad ? loadedLoad : idleLoad)[0], loadAverage);
                    (withLoad ? loadedLoad : idleLoad)[1] = Math.max((withLoad ? loadedLoad : idleLoad)[1], loadAverage);
                    try {
                        run(work, "triad-repeat.log", timeout, withLoad ? solve : idleSolve);
                    } finally {
                        if (load != null) load.stop();
                    }
                    (withLoad ? loaded : idle).add(check(domain, problem, triadPlan)[0]);
                }
                List<String> all = new ArrayList<>(idle);
                all.addAll(loaded);
                all.add(t[0]);
                // "-": no plan within the cap (a slow run on a loaded machine), not another plan
                List<String> lengths = all.stream().filter(x -> !x.equals("-")).distinct().toList();
                long capped = all.stream().filter(x -> x.equals("-")).count();
                boolean same = lengths.size() <= 1;
                if (!same) varying++;
                repeated = " " + (same && !lengths.isEmpty() ? "all " + lengths.get(0) + (capped > 0 ? " (" + capped + " of " + all.size() + " runs stopped at the cap)" : "")
                        : String.join(" ", idle) + " / " + String.join(" ", loaded)) + " |";
            }
            if (!t[0].equals("-") && !f[0].equals("-")) timeRatios.add(triadS / fdS);
            if (Files.exists(triadCpu) && !Double.isNaN(fdS) && !t[0].equals("-") && !f[0].equals("-")) cpuRatios.add(Double.parseDouble(cpu) / fdS);
            System.out.printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s |%s%n", args[i], seconds(triadS, t), cpu, t[0], t[1], seconds(fdS, f), f[0], f[1], ratio,
                    repeated);
            if (t[0].equals("-")) notes.add(args[i] + ": " + (Double.isNaN(triadS) ? "killed at the cap" : firstLine(work.resolve("triad.log"))));
        }
        java.util.Collections.sort(ratios);
        if (!ratios.isEmpty()) {
            int n = ratios.size();
            double median = n % 2 == 1 ? ratios.get(n / 2) : (ratios.get(n / 2 - 1) + ratios.get(n / 2)) / 2;
            long above = ratios.stream().filter(r -> r > 1.1 + 1e-9).count();
            System.out.printf("%nmedian length ratio %.2f over %d problems both solved; %d above 1.1%n", median, n, above);
        }
        if (!timeRatios.isEmpty()) System.out.printf("median whole-process time ratio (Triad wall / FD wall) %.2f, (Triad CPU / FD wall) %.2f%n",
                median(timeRatios), cpuRatios.isEmpty() ? Double.NaN : median(cpuRatios));
        if (repeat > 0) {
            System.out.printf("%nproblems whose %d repeated runs (idle and loaded) gave more than one length: %d%n", 2 * repeat, varying);
            System.out.printf("idle runs at nice -10, load average %.1f-%.1f at their start; loaded runs beside %d busy threads, load average %.1f-%.1f%n",
                    idleLoad[0], idleLoad[1], 2 * Runtime.getRuntime().availableProcessors(), loadedLoad[0], loadedLoad[1]);
        }
        if (!notes.isEmpty()) {
            System.out.println();
            System.out.println("Triad without a plan:");
            for (String n : notes) System.out.println("- " + n);
        }
    }

    private static double median(List<Double> values) {
        List<Double> v = new ArrayList<>(values);
        java.util.Collections.sort(v);
        int n = v.size();
        return n % 2 == 1 ? v.get(n / 2) : (v.get(n / 2 - 1) + v.get(n / 2)) / 2;
    }

    /** Busy threads beside the measured process, so that it runs on a loaded machine. */
    private static final class CpuLoad {
        private final java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean();
        private final List<Thread> threads = new ArrayList<>();

        CpuLoad(int n) {
            for (int i = 0; i < n; i++) {
                Thread t = new Thread(() -> {
                    long x = 1;
                    while (!stop.get()) x = x * 6364136223846793005L + 1;
                    if (x == 42) System.out.print("");
                });
                t.setDaemon(true);
                t.start();
                threads.add(t);
            }
        }

        void stop() throws InterruptedException {
            stop.set(true);
            for (Thread t : threads) t.join();
        }
    }

    /** The first line of Triad's output (its status and reason when it found no plan), shortened. */
    private static String firstLine(Path log) throws IOException {
        String text = Files.exists(log) ? Files.readString(log).strip() : "";
        String line = text.isEmpty() ? "(no output)" : text.lines().findFirst().orElse("");
        return line.length() > 240 ? line.substring(0, 240) + "..." : line;
    }

    private static String seconds(double s, String[] check) {
        return check[0].equals("-") ? (Double.isNaN(s) ? "timeout" : "no plan") : String.format("%.2f", s);
    }

    /** Wall seconds of the process, NaN if it hit the cap. */
    private static double run(Path dir, String log, double timeout, List<String> command) throws IOException, InterruptedException {
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(log).toFile()).start();
        if (!p.waitFor((long) (timeout * 1000) + 5000, TimeUnit.MILLISECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            p.waitFor();
            return Double.NaN;
        }
        return (System.nanoTime() - t0) / 1e9;
    }

    /** [length, valid] of a plan file, "-" if there is none. */
    private static String[] check(Domain domain, Problem problem, Path plan) throws IOException {
        if (!Files.exists(plan)) return new String[] {"-", "-"};
        PddlPlan p = ExternalPlanner.parsePlan(Files.readString(plan));
        if (domain == null) return new String[] {Integer.toString(p.length()), "not checked"};
        return new String[] {Integer.toString(p.length()), PlanValidator.validate(domain, problem, p).valid() ? "yes" : "NO"};
    }
}
