package org.triad.planner;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Benchmark main (not a test): Triad against Metric-FF 2.1 on numeric PDDL problems, each planner as a
 * whole process ({@code java ... SolveOnce} and {@code ff -o D -f P -s 0}), one run each with a time cap,
 * every plan checked by VAL ({@code Validate D P PLAN}: valid, and the metric's final value) and by
 * Triad's {@link PlanValidator} (VALIDATE {@code -}: Triad's validator only). Metric-FF reads {@code :fluents}, so it gets a copy of the domain with
 * {@code :numeric-fluents} renamed. Prints a Markdown table; reads only local files:
 * {@code MetricFfComparison METRIC_FF VALIDATE TIMEOUT_S DOMAIN.pddl PROBLEM.pddl [DOMAIN.pddl PROBLEM.pddl]...}
 * (Metric-FF and VAL built from their public sources, see ../shared/notes/reference-planners.md).
 */
public final class MetricFfComparison {
    public static void main(String[] args) throws Exception {
        if (args.length < 5 || (args.length - 3) % 2 != 0) {
            System.err.println("usage: MetricFfComparison METRIC_FF VALIDATE TIMEOUT_S DOMAIN PROBLEM [DOMAIN PROBLEM]...");
            System.exit(2);
        }
        Path ff = Path.of(args[0]).toAbsolutePath();
        Path validate = args[1].equals("-") ? null : Path.of(args[1]).toAbsolutePath();
        double timeout = Double.parseDouble(args[2]);
        Path work = Files.createTempDirectory("triad-mff");
        System.out.printf("Java %s, %d cores, load average at start %.1f, cap %.0f s per planner and problem%n%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), timeout);
        System.out.println("| problem | Triad s | Triad length | Triad VAL | Triad metric | Triad PlanValidator | Metric-FF s | Metric-FF length | Metric-FF VAL"
                + " | Metric-FF metric | Metric-FF PlanValidator |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        int both = 0, triadOnly = 0, ffOnly = 0, neither = 0;
        for (int i = 3; i < args.length; i += 2) {
            Path domain = Path.of(args[i]).toAbsolutePath();
            Path problem = Path.of(args[i + 1]).toAbsolutePath();
            String label = domain.getParent().getFileName() + "/" + problem.getFileName();
            Path triadPlan = work.resolve("triad-" + i + ".plan");
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            long t0 = System.nanoTime();
            boolean triadSolved = run(List.of(java, "-Xmx2g", "-cp", System.getProperty("java.class.path"), SolveOnce.class.getName(),
                    domain.toString(), problem.toString(), triadPlan.toString(), Double.toString(timeout)), timeout + 30, work.resolve("triad.out"))
                    && Files.exists(triadPlan);
            double triadS = (System.nanoTime() - t0) / 1e9;
            Path ffDomain = work.resolve("ff-domain-" + i + ".pddl");
            Files.writeString(ffDomain, Files.readString(domain).replaceAll("(?i):numeric-fluents", ":fluents"));
            Path ffOut = work.resolve("ff-" + i + ".out");
            t0 = System.nanoTime();
            run(List.of(ff.toString(), "-o", ffDomain.toString(), "-f", problem.toString(), "-s", "0"), timeout, ffOut);
            double ffS = (System.nanoTime() - t0) / 1e9;
            List<String> ffSteps = metricFfPlan(Files.readString(ffOut));
            Path ffPlan = work.resolve("ff-" + i + ".plan");
            if (ffSteps != null) Files.writeString(ffPlan, String.join("\n", ffSteps) + "\n");
            String[] triadVal = triadSolved && validate != null ? val(validate, domain, problem, triadPlan, work) : new String[] { "-", "-" };
            String[] ffVal = ffSteps != null && validate != null ? val(validate, domain, problem, ffPlan, work) : new String[] { "-", "-" };
            int triadLen = triadSolved ? (int) Files.readAllLines(triadPlan).stream().filter(l -> l.startsWith("(")).count() : 0;
            System.out.printf(Locale.ROOT, "| %s | %.2f | %s | %s | %s | %s | %.2f | %s | %s | %s | %s |%n", label, triadS, triadSolved ? triadLen : "-",
                    triadVal[0], triadVal[1], triadSolved ? replay(domain, problem, Files.readAllLines(triadPlan)) : "-", ffS,
                    ffSteps != null ? ffSteps.size() : "-", ffVal[0], ffVal[1], ffSteps != null ? replay(domain, problem, ffSteps) : "-");
            if (triadSolved && ffSteps != null) both++;
            else if (triadSolved) triadOnly++;
            else if (ffSteps != null) ffOnly++;
            else neither++;
        }
        System.out.printf("%nsolved by both %d, by Triad only %d, by Metric-FF only %d, by neither %d%n", both, triadOnly, ffOnly, neither);
    }

    /** Triad's {@link PlanValidator} on a plan given as {@code (action args)} lines. */
    private static String replay(Path domain, Path problem, List<String> lines) {
        List<PddlStep> steps = new ArrayList<>();
        for (String l : lines) {
            String t = l.trim();
            if (!t.startsWith("(")) continue;
            String[] parts = t.substring(1, t.length() - 1).trim().split("\\s+");
            steps.add(new PddlStep(parts[0], List.of(parts).subList(1, parts.length)));
        }
        try {
            PlanValidator.Report r = PlanValidator.validate(org.triad.planner.pddl.PddlParser.parseDomain(domain),
                    org.triad.planner.pddl.PddlParser.parseProblem(problem), new PddlPlan(steps));
            return r.valid() ? "valid" : "INVALID: " + r.message().replace('|', '/');
        } catch (Exception e) {
            return "error: " + e.getMessage();
        }
    }

    private static boolean run(List<String> command, double timeoutS, Path output) throws Exception {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile()).start();
        if (!p.waitFor((long) (timeoutS * 1000), TimeUnit.MILLISECONDS)) {
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

    /** VAL's verdict ("valid" or its first complaint) and the metric's final value. */
    private static String[] val(Path validate, Path domain, Path problem, Path plan, Path work) throws Exception {
        Path out = work.resolve("val.out");
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
        return new String[] { text.contains("Plan valid") ? "valid" : "INVALID", metric };
    }
}
