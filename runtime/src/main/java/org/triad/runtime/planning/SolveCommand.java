package org.triad.runtime.planning;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.ServiceLoader;
import org.triad.runtime.pddl.Domain;
import org.triad.runtime.pddl.PddlParseException;
import org.triad.runtime.pddl.PddlParser;
import org.triad.runtime.pddl.Problem;

/**
 * {@code solve DOMAIN.pddl PROBLEM.pddl [-o PLAN] [--planner triad|pddl4j] [--timeout SECONDS]}:
 * prints the plan as VAL reads it. Exit status 0 solved, 1 no plan (unsolvable or timeout),
 * 2 usage, input or planner error.
 */
public final class SolveCommand {
    static final String USAGE = "usage: solve DOMAIN.pddl PROBLEM.pddl [-o PLAN] [--planner triad|pddl4j] [--timeout SECONDS]";

    private SolveCommand() { }

    public static void main(String[] args) {
        System.exit(run(Arrays.asList(args), System.out, System.err));
    }

    public static int run(List<String> args, PrintStream out, PrintStream err) {
        String domainFile = null;
        String problemFile = null;
        String planFile = null;
        String plannerName = "triad";
        double timeoutSeconds = 60;
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            switch (a) {
                case "-o", "--planner", "--timeout" -> {
                    if (i + 1 >= args.size()) return usage(err, "missing value after " + a);
                    String v = args.get(++i);
                    if (a.equals("-o")) {
                        planFile = v;
                    } else if (a.equals("--planner")) {
                        plannerName = v;
                    } else {
                        try {
                            timeoutSeconds = Double.parseDouble(v);
                        } catch (NumberFormatException e) {
                            return usage(err, "--timeout expects seconds, got '" + v + "'");
                        }
                        if (!(timeoutSeconds > 0)) return usage(err, "--timeout must be positive, got '" + v + "'");
                    }
                }
                case "-h", "--help" -> {
                    out.println(USAGE);
                    return 0;
                }
                default -> {
                    if (a.startsWith("-")) return usage(err, "unknown option " + a);
                    if (domainFile == null) domainFile = a;
                    else if (problemFile == null) problemFile = a;
                    else return usage(err, "unexpected argument " + a);
                }
            }
        }
        if (problemFile == null) return usage(err, "expected a domain and a problem file");
        Planner planner = planner(plannerName);
        if (planner == null) return usage(err, "unknown planner '" + plannerName + "' (triad or pddl4j; pddl4j needs triad-pddl4j on the class path)");
        Domain domain;
        Problem problem;
        try {
            domain = PddlParser.parseDomain(Path.of(domainFile));
            problem = PddlParser.parseProblem(Path.of(problemFile));
        } catch (PddlParseException e) {
            err.println("error: " + e.getMessage());
            return 2;
        } catch (NoSuchFileException e) {
            err.println("error: no such file: " + e.getFile());
            return 2;
        } catch (IOException e) {
            err.println("error: cannot read input: " + e.getMessage());
            return 2;
        }
        PlanResult r = planner.solve(domain, problem, Duration.ofMillis((long) (timeoutSeconds * 1000)));
        switch (r.status()) {
            case SOLVED -> {
                String text = r.plan().toPddl();
                out.print(text);
                if (planFile != null) {
                    try {
                        Files.writeString(Path.of(planFile), text);
                    } catch (IOException e) {
                        err.println("error: cannot write plan file " + planFile + ": " + e.getMessage());
                        return 2;
                    }
                }
                return 0;
            }
            case UNSOLVABLE -> {
                err.println("no plan: problem is unsolvable (" + r.message() + ")");
                return 1;
            }
            case TIMEOUT -> {
                err.println("no plan: time limit of " + timeoutSeconds + " s reached");
                return 1;
            }
            default -> {
                err.println("error: " + r.message());
                return 2;
            }
        }
    }

    private static int usage(PrintStream err, String problem) {
        err.println("error: " + problem);
        err.println(USAGE);
        return 2;
    }

    /** Triad's engine, or another planner found through {@link ServiceLoader} by {@link Planner#name()}. */
    static Planner planner(String name) {
        if (name.equals("triad")) return new TriadPlanner();
        for (Planner p : ServiceLoader.load(Planner.class)) {
            if (p.name().equals(name)) return p;
        }
        return null;
    }
}
