package org.triad.planner;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.pddl.Problem;

/**
 * Runs an external planner executable given by a command template with the placeholders
 * {@code {domain}}, {@code {problem}} and {@code {plan}}, e.g. {@code ff -o {domain} -f {problem}} or
 * {@code fast-downward.py --alias lama-first --plan-file {plan} {domain} {problem}}. Reads the plan
 * from the plan file when the planner wrote one, else from its standard output, in either the
 * {@code (move a b)} form (optionally with {@code 0.000:} time stamps) or FF's {@code step 0: MOVE A B}.
 */
public final class ExternalPlanner implements PddlPlanner {
    private static final Pattern PAREN = Pattern.compile("^\\s*(?:[0-9.]+\\s*:\\s*)?\\(([^()]+)\\)");
    private static final Pattern FF_STEP = Pattern.compile("^\\s*(?:step)?\\s*\\d+\\s*:\\s*([A-Za-z][^()]*?)\\s*$", Pattern.CASE_INSENSITIVE);

    private final String name;
    private final List<String> template;

    /** {@code template} is split on white space; each word may contain placeholders. */
    public ExternalPlanner(String name, String template) {
        this.name = name;
        this.template = List.of(template.trim().split("\\s+"));
        if (template.isBlank()) throw new IllegalArgumentException("empty command template");
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public SolveResult solve(Domain domain, Problem problem, Duration timeout) {
        long start = System.nanoTime();
        Path dir = null;
        try {
            dir = Files.createTempDirectory("triad-plan");
            Path d = dir.resolve("domain.pddl");
            Path p = dir.resolve("problem.pddl");
            Path plan = dir.resolve("plan.txt");
            Files.writeString(d, PddlWriter.write(domain));
            Files.writeString(p, PddlWriter.write(problem));
            List<String> cmd = new ArrayList<>();
            for (String w : template) {
                cmd.add(w.replace("{domain}", d.toString()).replace("{problem}", p.toString()).replace("{plan}", plan.toString()));
            }
            Path out = dir.resolve("stdout.txt");
            Path err = dir.resolve("stderr.txt");
            Process proc;
            try {
                proc = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            } catch (IOException e) {
                return SolveResult.error("cannot start planner '" + cmd.get(0) + "': " + e.getMessage());
            }
            boolean finished;
            try {
                finished = proc.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                finished = false;
            }
            SolveResult.Stats stats = new SolveResult.Stats(0, (System.nanoTime() - start) / 1e6, 0, 0);
            if (!finished) {
                proc.descendants().forEach(ProcessHandle::destroyForcibly);
                proc.destroyForcibly();
                return SolveResult.timeout(stats);
            }
            String stdout = Files.readString(out, StandardCharsets.UTF_8);
            String stderr = Files.readString(err, StandardCharsets.UTF_8);
            Path planFile = Files.exists(plan) ? plan : null;
            if (planFile != null) return SolveResult.solved(parsePlan(Files.readString(planFile)), stats);
            List<PddlStep> steps = parseSteps(stdout);
            boolean claimsSolution = !steps.isEmpty() || stdout.toLowerCase(Locale.ROOT).contains("found legal plan");
            if (claimsSolution && proc.exitValue() == 0) return SolveResult.solved(new PddlPlan(steps), stats);
            String all = (stdout + "\n" + stderr).toLowerCase(Locale.ROOT);
            if (all.contains("unsolvable") || proc.exitValue() == 11 || proc.exitValue() == 12) {
                return SolveResult.unsolvable(name + " reports the problem unsolvable", stats);
            }
            return SolveResult.error(name + " exited with status " + proc.exitValue() + " without a plan" + tail(stderr.isBlank() ? stdout : stderr));
        } catch (IOException e) {
            return SolveResult.error("planner I/O failed: " + e.getMessage());
        } finally {
            if (dir != null) deleteQuietly(dir);
        }
    }

    private static String tail(String text) {
        String t = text.strip();
        if (t.isEmpty()) return "";
        return ": " + (t.length() > 300 ? "..." + t.substring(t.length() - 300) : t);
    }

    /** Parses a plan in the {@code (move a b)} or FF {@code step 0: MOVE A B} form. */
    public static PddlPlan parsePlan(String text) {
        return new PddlPlan(parseSteps(text));
    }

    private static List<PddlStep> parseSteps(String text) {
        List<PddlStep> paren = new ArrayList<>();
        List<PddlStep> ff = new ArrayList<>();
        boolean inFfPlan = false;
        for (String line : text.split("\\R")) {
            String l = line.strip();
            if (l.startsWith(";")) continue;
            Matcher m = PAREN.matcher(l);
            if (m.find()) {
                paren.add(action(m.group(1)));
                continue;
            }
            if (l.toLowerCase(Locale.ROOT).startsWith("step")) inFfPlan = true;
            if (inFfPlan) {
                Matcher s = FF_STEP.matcher(l);
                if (s.matches()) ff.add(action(s.group(1)));
                else if (!l.isEmpty()) inFfPlan = false;
            }
        }
        return paren.isEmpty() ? ff : paren;
    }

    private static PddlStep action(String body) {
        String[] words = body.strip().toLowerCase(Locale.ROOT).split("\\s+");
        List<String> args = new ArrayList<>(List.of(words).subList(1, words.length));
        return new PddlStep(words[0], args);
    }

    private static void deleteQuietly(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // a leftover temp directory is harmless
        }
    }
}
