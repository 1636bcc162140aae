package org.triad.planner;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;

/**
 * One solve in a fresh JVM, as {@code ./triad solve} does it but without the command-line tool's
 * class path: {@code SolveOnce DOMAIN PROBLEM PLAN TIMEOUT_S}. Writes the plan; exit 0 solved, 1 not.
 * Used by {@link FastDownwardComparison} to time the whole process like Fast Downward's. The process's
 * CPU seconds so far go to {@code PLAN.cpu} when it ends with or without a plan (on a loaded machine
 * the wall time says more about the load than about the planner).
 */
public final class SolveOnce {
    public static void main(String[] args) throws Exception {
        SolveResult r;
        try {
            r = new TriadEngine().solve(PddlParser.parseDomain(Path.of(args[0])), PddlParser.parseProblem(Path.of(args[1])),
                    Duration.ofMillis((long) (Double.parseDouble(args[3]) * 1000)));
        } catch (PddlParseException e) {
            System.err.println("PARSE ERROR: " + e.getMessage());
            System.exit(1);
            return;
        }
        Files.writeString(Path.of(args[2] + ".cpu"), Double.toString(
                ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime() / 1e9));
        if (!r.isSolved()) {
            System.err.println(r.status() + ": " + r.message());
            System.exit(1);
        }
        Files.writeString(Path.of(args[2]), r.plan().toPddl());
    }
}
