package org.triad.pddl4j;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;
import org.triad.planner.SolveResult;
import org.triad.planner.PddlPlanner;
import org.triad.planner.TriadEngine;

/**
 * Benchmark main (not a test): PDDL4J FF against the Triad engine on small hospital problems, warm
 * JVM, median wall ms of a complete call (a fresh Triad planner each time, so grounding included).
 * Run after {@code mvn -B -q -pl runtime,pddl4j -am verify}:
 * {@code java -Xmx256m -cp pddl4j/target/triad-pddl4j-0.1.0-SNAPSHOT.jar:pddl4j/target/test-classes:runtime/target/classes:LOG4J_API_JAR:LOG4J_CORE_JAR org.triad.pddl4j.Pddl4jComparison ../shared/benchmarks/planning/hospital}
 */
public final class Pddl4jComparison {
    public static void main(String[] args) throws Exception {
        Path dir = Path.of(args.length > 0 ? args[0] : "../shared/benchmarks/planning/hospital");
        Domain domain = PddlParser.parseDomain(dir.resolve("domain.pddl"));
        Duration timeout = Duration.ofSeconds(10);
        System.out.println("| problem | PDDL4J FF ms | PDDL4J length | Triad ms (ground+search) | Triad length |");
        System.out.println("|---|---|---|---|---|");
        for (String n : new String[] {"10", "50", "100", "200"}) {
            for (String v : new String[] {"a", "b", "c"}) {
                Problem p = PddlParser.parseProblem(dir.resolve("p-" + n + "-" + v + ".pddl"));
                String[] pd = measure(new Pddl4jPlanner(), domain, p, timeout);
                String[] tr = measure(null, domain, p, timeout);
                System.out.printf("| p-%s-%s | %s | %s | %s | %s |%n", n, v, pd[0], pd[1], tr[0], tr[1]);
            }
        }
    }

    /** Median ms and plan length (or the status) over 1 warm-up + 5 runs; one run if it fails. */
    private static String[] measure(PddlPlanner fixed, Domain d, Problem p, Duration timeout) {
        double[] ms = new double[5];
        SolveResult last = null;
        for (int i = 0; i < 6; i++) {
            PddlPlanner planner = fixed != null ? fixed : new TriadEngine();
            long t0 = System.nanoTime();
            last = planner.solve(d, p, timeout);
            double t = (System.nanoTime() - t0) / 1e6;
            if (!last.isSolved()) return new String[] {String.format("%.0f", t), last.status().toString()};
            if (i > 0) ms[i - 1] = t;
        }
        Arrays.sort(ms);
        return new String[] {String.format("%.1f", ms[2]), Integer.toString(last.plan().length())};
    }
}
