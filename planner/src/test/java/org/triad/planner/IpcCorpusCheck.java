package org.triad.planner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Corpus check (a main, not a test): parses every problem of the given domain folders of a local
 * copy of the IPC benchmark collection Fast Downward uses (github.com/aibasel/downward-benchmarks),
 * each with its domain file found as Fast Downward finds it, and with {@code --ground} also grounds
 * it. Prints one line per domain and every failure; exit 1 if any problem failed. Reads only local
 * files. Run through {@code planner/scripts/check-ipc-corpus.sh}.
 */
public final class IpcCorpusCheck {
    public static void main(String[] args) throws IOException {
        boolean ground = false;
        List<String> rest = new ArrayList<>();
        for (String a : args) {
            if (a.equals("--ground")) ground = true; else rest.add(a);
        }
        if (rest.isEmpty()) {
            System.err.println("usage: IpcCorpusCheck [--ground] CORPUS_DIR [DOMAIN_FOLDER...]");
            System.exit(2);
        }
        Path root = Path.of(rest.get(0));
        List<String> folders = rest.subList(1, rest.size());
        if (folders.isEmpty()) {
            try (Stream<Path> s = Files.list(root)) {
                folders = s.filter(Files::isDirectory).map(p -> p.getFileName().toString()).filter(n -> !n.startsWith(".")).sorted().toList();
            }
        }
        int problems = 0;
        int failed = 0;
        int skipped = 0;
        Map<String, Integer> failures = new TreeMap<>();
        long start = System.nanoTime();
        for (String folder : folders) {
            Path dir = root.resolve(folder);
            if (!Files.isDirectory(dir)) {
                System.out.println(folder + ": no such folder under " + root);
                failed++;
                continue;
            }
            List<Path> files;
            try (Stream<Path> s = Files.list(dir)) {
                files = s.filter(p -> p.toString().endsWith(".pddl") && !p.getFileName().toString().contains("domain")).sorted().toList();
            }
            int ok = 0;
            int actions = 0;
            for (Path p : files) {
                problems++;
                Path d = domainOf(p);
                if (d == null) {
                    // the snapshot may lack a (large) domain file; that says nothing about the parser
                    skipped++;
                    System.out.println("  SKIP " + root.relativize(p) + ": no domain file beside it");
                    continue;
                }
                try {
                    Domain domain = PddlParser.parseDomain(d);
                    Problem problem = PddlParser.parseProblem(p);
                    if (ground) actions += new GroundedProblem(domain, problem).actionCount();
                    ok++;
                } catch (PddlParseException | PlanningInputException e) {
                    failed++;
                    failures.merge(folder, 1, Integer::sum);
                    System.out.println("  FAIL " + root.relativize(p) + ": " + e.getMessage());
                } catch (RuntimeException | StackOverflowError | OutOfMemoryError e) {
                    failed++;
                    failures.merge(folder, 1, Integer::sum);
                    System.out.println("  CRASH " + root.relativize(p) + ": " + e);
                }
            }
            System.out.printf("%-40s %3d/%3d %s%s%n", folder, ok, files.size(), ground ? "grounded" : "parsed", ground ? ", " + actions + " ground actions" : "");
        }
        System.out.printf("%d problems in %d domains, %d failed, %d skipped, %.1f s%n", problems, folders.size(), failed, skipped, (System.nanoTime() - start) / 1e9);
        if (!failures.isEmpty()) System.out.println("failures by domain: " + failures);
        System.exit(failed == 0 ? 0 : 1);
    }

    /** The domain file of a problem, looked up by the names Fast Downward's driver tries. */
    static Path domainOf(Path problem) {
        Path dir = problem.getParent();
        String base = problem.getFileName().toString();
        String stem = base.substring(0, base.length() - ".pddl".length());
        List<String> candidates = List.of("domain.pddl", base.substring(0, Math.min(3, base.length())) + "-domain.pddl",
                stem + "-domain.pddl", "domain_" + base, "domain-" + base);
        for (String c : candidates) {
            if (Files.isRegularFile(dir.resolve(c))) return dir.resolve(c);
        }
        return null;
    }
}
