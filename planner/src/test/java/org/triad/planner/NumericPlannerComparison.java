package org.triad.planner;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.PlanMetric;
import org.triad.planner.pddl.Problem;

/**
 * Benchmark main (not a test): Triad against Metric-FF 2.1 and ENHSP on numeric PDDL problems, each
 * planner as a whole process with a time cap ({@code java ... SolveOnce}; {@code ff -o D -f P}, with
 * {@code -s 0} when the problem has no {@code :metric} and its cost-minimising default otherwise;
 * {@code java -jar enhsp.jar -o D -f P -h hadd -s gbfs}); every plan checked by VAL ({@code Validate D P PLAN}:
 * valid, and the metric's final value) and by Triad's {@link PlanValidator}. A plan's cost is the metric's
 * value where the problem has one (VAL's, else PlanValidator's), else its length; the ratio is Triad's cost
 * over the better of the others' (for a maximised metric, the other way round). Metric-FF reads
 * {@code :fluents}, so it gets a copy of the domain with {@code :numeric-fluents} renamed. Prints a Markdown
 * table; reads only local files. Usage:
 * {@code NumericPlannerComparison [--parallel] METRIC_FF|- VALIDATE|- ENHSP_JAR|- TIMEOUT_S DOMAIN PROBLEM [DOMAIN PROBLEM]...}
 * ({@code -} leaves a tool out; how to build them: {@code planner/scripts/reference-planners.sh}). With
 * {@code --parallel} the three planners of one problem run at the same time (faster, noisier seconds).
 */
public final class NumericPlannerComparison {
    private record Outcome(boolean solved, double seconds, List<String> steps, String val, String valMetric, String replay, double cost) { }

    /**
     * Triad's JVM as {@code ./triad solve} starts it (the launcher's flags for a process that plans once:
     * the serial collector and the C1 compiler only, which on settlersnumeric p2 saves a third of the CPU
     * the C2 compiler spends), so that the table times what a user runs.
     */
    static final List<String> TRIAD_JVM = List.of("-Xmx2g", "-XX:+UseSerialGC", "-XX:-UsePerfData", "-XX:TieredStopAtLevel=1");

    public static void main(String[] argv) throws Exception {
        List<String> args = new ArrayList<>(List.of(argv));
        boolean parallel = args.remove("--parallel");
        if (args.size() < 6 || (args.size() - 4) % 2 != 0) {
            System.err.println("usage: NumericPlannerComparison [--parallel] METRIC_FF|- VALIDATE|- ENHSP_JAR|- TIMEOUT_S DOMAIN PROBLEM [DOMAIN PROBLEM]...");
            System.exit(2);
        }
        Path ff = args.get(0).equals("-") ? null : Path.of(args.get(0)).toAbsolutePath();
        Path validate = args.get(1).equals("-") ? null : Path.of(args.get(1)).toAbsolutePath();
        Path enhsp = args.get(2).equals("-") ? null : Path.of(args.get(2)).toAbsolutePath();
        double timeout = Double.parseDouble(args.get(3));
        Path work = Files.createTempDirectory("triad-numeric");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        System.out.printf("Java %s, %d cores, load average at start %.1f, cap %.0f s per planner and problem%s%n%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), timeout, parallel ? ", the three planners side by side" : "");
        System.out.println("| problem | metric | Triad s | Triad CPU s | Triad cost | Triad VAL | Metric-FF s | Metric-FF cost | Metric-FF VAL | ENHSP s | ENHSP cost | ENHSP VAL | ratio | load |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        int problems = 0, triadSolved = 0, othersSolved = 0, missed = 0, within = 0, compared = 0;
        List<Double> ratios = new ArrayList<>();
        // daemon threads: a tool that fails (VAL missing) ends the run with its exception instead of leaving the JVM waiting
        ExecutorService pool = Executors.newFixedThreadPool(parallel ? 3 : 1, r -> {
            Thread t = new Thread(r, "planner");
            t.setDaemon(true);
            return t;
        });
        for (int i = 4; i < args.size(); i += 2) {
            Path domain = Path.of(args.get(i)).toAbsolutePath();
            Path problem = Path.of(args.get(i + 1)).toAbsolutePath();
            String label = domain.getParent().getFileName() + "/" + problem.getFileName();
            Domain d = PddlParser.parseDomain(domain);
            Problem p = PddlParser.parseProblem(problem);
            PlanMetric metric = PlanMetric.of(p);
            int n = i;
            Path ffDomain = work.resolve("ff-domain-" + n + ".pddl");
            Files.writeString(ffDomain, Files.readString(domain).replaceAll("(?i):numeric-fluents", ":fluents"));
            Future<Outcome> triad = pool.submit(() -> {
                Path plan = work.resolve("triad-" + n + ".plan");
                List<String> cmd = new ArrayList<>(List.of(java));
                cmd.addAll(TRIAD_JVM);
                cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), SolveOnce.class.getName(), domain.toString(), problem.toString(),
                        plan.toString(), Double.toString(timeout)));
                return outcome(cmd, timeout + 30, work.resolve("triad-" + n + ".out"), plan, null, domain, problem, d, p, metric, validate, work);
            });
            Future<Outcome> mff = ff == null ? null : pool.submit(() -> {
                List<String> cmd = new ArrayList<>(List.of(ff.toString(), "-o", ffDomain.toString(), "-f", problem.toString()));
                if (metric == null) cmd.addAll(List.of("-s", "0"));
                return outcome(cmd, timeout, work.resolve("ff-" + n + ".out"), work.resolve("ff-" + n + ".plan"), "ff", domain, problem, d, p, metric,
                        validate, work);
            });
            Future<Outcome> enh = enhsp == null ? null : pool.submit(() -> {
                Path plan = work.resolve("enhsp-" + n + ".plan");
                return outcome(List.of(java, "-Xmx2g", "-jar", enhsp.toString(), "-o", domain.toString(), "-f", problem.toString(), "-sp", plan.toString(),
                        "-npm", "-h", "hadd", "-s", "gbfs"), timeout, work.resolve("enhsp-" + n + ".out"), plan, null, domain, problem, d, p, metric,
                        validate, work);
            });
            Outcome t = triad.get();
            Outcome m = mff == null ? null : mff.get();
            Outcome e = enh == null ? null : enh.get();
            problems++;
            if (t.solved) triadSolved++;
            double better = Double.NaN;
            boolean maximize = metric != null && !metric.minimize();
            for (Outcome o : new Outcome[] { m, e }) {
                if (o == null || !o.solved || Double.isNaN(o.cost)) continue;
                better = Double.isNaN(better) ? o.cost : maximize ? Math.max(better, o.cost) : Math.min(better, o.cost);
            }
            boolean othersSolve = m != null && m.solved || e != null && e.solved;
            if (othersSolve) othersSolved++;
            if (othersSolve && !t.solved) missed++;
            String ratio = "-";
            if (t.solved && !Double.isNaN(better) && !Double.isNaN(t.cost)) {
                double r = maximize ? (t.cost == 0 ? Double.NaN : better / t.cost) : better == 0 ? (t.cost == 0 ? 1 : Double.NaN) : t.cost / better;
                if (!Double.isNaN(r)) {
                    compared++;
                    ratios.add(r);
                    if (r <= 1.1 + 1e-9) within++;
                    ratio = String.format(Locale.ROOT, "%.2f", r);
                }
            }
            System.out.printf(Locale.ROOT, "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f |%n", label, metric == null ? "length" : metric,
                    seconds(t), cpu(work.resolve("triad-" + i + ".plan.cpu")), cost(t), t.solved ? t.val : "-", seconds(m), cost(m), m != null && m.solved ? m.val : "-", seconds(e), cost(e),
                    e != null && e.solved ? e.val : "-", ratio, ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
        pool.shutdown();
        ratios.sort(null);
        System.out.printf(Locale.ROOT, "%n%d problems: Triad solved %d, Metric-FF or ENHSP %d; solved by another but not by Triad: %d;"
                + " Triad's cost within 1.1x of the better other's on %d of %d both solved (median ratio %s)%n", problems, triadSolved, othersSolved,
                missed, within, compared, ratios.isEmpty() ? "-" : String.format(Locale.ROOT, "%.2f", ratios.get(ratios.size() / 2)));
    }

    private static String seconds(Outcome o) {
        return o == null ? "-" : String.format(Locale.ROOT, "%.2f", o.seconds);
    }

    /** The CPU seconds {@link SolveOnce} wrote for its whole JVM, or "-" when it was killed at the cap before writing them. */
    private static String cpu(Path file) {
        try {
            return Files.exists(file) ? String.format(Locale.ROOT, "%.2f", Double.parseDouble(Files.readString(file).trim())) : "-";
        } catch (java.io.IOException | NumberFormatException e) {
            return "-";
        }
    }

    private static String cost(Outcome o) {
        if (o == null || !o.solved) return "-";
        return Double.isNaN(o.cost) ? "?" : PddlWriterNumber.of(o.cost);
    }

    /** Runs one planner; its plan is read from {@code plan} (or from Metric-FF's output when {@code format} is "ff"). */
    private static Outcome outcome(List<String> command, double timeoutS, Path output, Path plan, String format, Path domain, Path problem,
                                   Domain d, Problem p, PlanMetric metric, Path validate, Path work) throws Exception {
        long t0 = System.nanoTime();
        boolean ended = run(command, timeoutS, output);
        double seconds = (System.nanoTime() - t0) / 1e9;
        List<String> steps = null;
        if ("ff".equals(format)) {
            steps = metricFfPlan(Files.readString(output));
            if (steps != null) Files.writeString(plan, String.join("\n", steps) + "\n");
        } else if (ended && Files.exists(plan)) {
            steps = Files.readAllLines(plan).stream().map(String::trim).filter(l -> l.startsWith("(")).map(l -> l.replaceAll("\\s+", " ")).toList();
        }
        if (steps == null) return new Outcome(false, seconds, null, "-", "-", "-", Double.NaN);
        String[] val = validate == null ? new String[] { "-", "-" } : val(validate, domain, problem, plan, work);
        PddlPlan parsed = parse(steps);
        PlanValidator.Report report = PlanValidator.validate(d, p, parsed);
        double cost = steps.size();
        if (metric != null) {
            OptionalDouble own = PlanValidator.metricValue(d, p, parsed);
            cost = !val[1].equals("-") ? Double.parseDouble(val[1]) : own.isPresent() ? own.getAsDouble() : Double.NaN;
        }
        boolean valid = validate != null && !val[0].startsWith("VAL cannot") ? val[0].equals("valid") : report.valid();
        String verdict = (validate == null ? "" : val[0]) + (report.valid() ? "" : " (PlanValidator: " + report.message().replace('|', '/') + ")");
        return new Outcome(valid, seconds, steps, verdict.isBlank() ? "valid (PlanValidator)" : verdict, val[1], report.toString(), cost);
    }

    private static PddlPlan parse(List<String> lines) {
        List<PddlStep> steps = new ArrayList<>();
        for (String t : lines) {
            String[] parts = t.substring(1, t.length() - 1).trim().split("\\s+");
            steps.add(new PddlStep(parts[0].toLowerCase(Locale.ROOT), List.of(parts).subList(1, parts.length).stream().map(s -> s.toLowerCase(Locale.ROOT)).toList()));
        }
        return new PddlPlan(steps);
    }

    private static boolean run(List<String> command, double timeoutS, Path output) throws Exception {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile()).start();
        if (!p.waitFor((long) (timeoutS * 1000), TimeUnit.MILLISECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly().waitFor();
            return false;
        }
        return p.exitValue() == 0;
    }

    /** The plan Metric-FF printed ("found legal plan as follows", then "step N: A X Y" lines), or null. */
    static List<String> metricFfPlan(String output) {
        int at = output.indexOf("found legal plan");
        if (at < 0) return null;
        List<String> steps = new ArrayList<>();
        Matcher m = Pattern.compile("(?m)^\\s*(?:step\\s+)?\\d+: (.+)$").matcher(output.substring(at));
        while (m.find()) {
            String step = m.group(1).trim().toLowerCase(Locale.ROOT);
            if (!step.equals("reach-goal")) steps.add("(" + step + ")"); // Metric-FF's own action for a goal it compiled
        }
        return steps;
    }

    /** VAL's verdict ("valid" or INVALID with its reason) and the metric's final value. */
    private static String[] val(Path validate, Path domain, Path problem, Path plan, Path work) throws Exception {
        Path out = Files.createTempFile(work, "val", ".out");
        ProcessBuilder pb = new ProcessBuilder(validate.toString(), domain.toString(), problem.toString(), plan.toString())
                .redirectErrorStream(true).redirectOutput(out.toFile());
        pb.environment().put("LD_LIBRARY_PATH", validate.getParent().toString());
        Process p = pb.start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor();
            return new String[] { "VAL timeout", "-" };
        }
        String text = Files.readString(out);
        Matcher value = Pattern.compile("Final value: (\\S+)").matcher(text);
        String metric = value.find() ? value.group(1) : "-";
        if (text.contains("Plan valid")) return new String[] { "valid", metric };
        // VAL's lexer takes a name that starts with a keyword (increase_z in drone) for the keyword
        // and it refuses some domains outright (sailing: "Problem in domain definition!")
        if (text.contains("Parser failed") || text.contains("Problem in domain definition")) return new String[] { "VAL cannot read it", "-" };
        Matcher why = Pattern.compile("(?m)^(Plan failed.*|.*[Uu]nsatisfied.*|.*[Ee]rror.*)$").matcher(text);
        return new String[] { "INVALID" + (why.find() ? ": " + why.group(1).trim().replace('|', '/') : ""), "-" };
    }

    /** Numbers as the table shows them. */
    private static final class PddlWriterNumber {
        static String of(double v) {
            return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : String.format(Locale.ROOT, "%.2f", v);
        }
    }
}
