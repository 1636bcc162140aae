package org.triad.pddl4j;

import fr.uga.pddl4j.encoding.CodedProblem;
import fr.uga.pddl4j.heuristics.relaxation.Heuristic;
import fr.uga.pddl4j.parser.ErrorManager;
import fr.uga.pddl4j.parser.Message;
import fr.uga.pddl4j.planners.ProblemFactory;
import fr.uga.pddl4j.planners.statespace.AbstractStateSpacePlanner;
import fr.uga.pddl4j.planners.statespace.ff.FF;
import fr.uga.pddl4j.planners.statespace.hsp.HSP;
import fr.uga.pddl4j.util.BitOp;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.apache.logging.log4j.Level;
import org.apache.logging.log4j.core.config.Configurator;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.pddl.Problem;
import org.triad.planner.PddlStep;
import org.triad.planner.PddlPlan;
import org.triad.planner.SolveResult;
import org.triad.planner.PlanValidator;
import org.triad.planner.PddlPlanner;

/**
 * PDDL4J 3.8.3 behind Triad's {@link PddlPlanner} interface. The AST is printed as PDDL and handed to
 * PDDL4J's parser; FF (enforced hill-climbing, then greedy search) or HSP searches with the timeout
 * passed explicitly in milliseconds (the default of 600 is silently read as ms). Calls are
 * serialised: PDDL4J keeps grounding state in static fields. Its loggers are switched off, since
 * without its memory-measuring agent every search logs an ERROR. Its plans are checked with
 * {@link PlanValidator}: 3.8.3 returns invalid plans on some inputs, reported here as errors.
 */
public final class Pddl4jPlanner implements PddlPlanner {
    /** Which PDDL4J search to run. */
    public enum Search { FF, HSP }

    private static final Object LOCK = new Object();

    static {
        Configurator.setLevel("fr.uga", Level.OFF);
    }

    private final Search search;

    /** FF, the default used by {@code solve --planner pddl4j}. */
    public Pddl4jPlanner() {
        this(Search.FF);
    }

    public Pddl4jPlanner(Search search) {
        this.search = search;
    }

    @Override
    public String name() {
        return "pddl4j";
    }

    @Override
    public SolveResult solve(Domain domain, Problem problem, Duration timeout) {
        Domain plain = withoutCosts(domain);
        String numbers = numbers(plain, problem);
        if (!numbers.isEmpty()) {
            return SolveResult.error("PDDL4J 3.8.3 has no numeric fluents, and this task computes with " + numbers
                    + ": plan it with the triad engine (--planner triad) or a numeric planner such as Metric-FF");
        }
        if (plain != domain) {
            domain = plain;
            problem = new Problem(problem.name(), problem.domainName(), problem.objects(), problem.init(), List.of(), problem.goal(), null);
        }
        Path dir = null;
        try {
            dir = Files.createTempDirectory("triad-pddl4j");
            File d = dir.resolve("domain.pddl").toFile();
            File p = dir.resolve("problem.pddl").toFile();
            Files.writeString(d.toPath(), PddlWriter.write(domain));
            Files.writeString(p.toPath(), PddlWriter.write(problem));
            SolveResult r;
            synchronized (LOCK) {
                r = solveLocked(d, p, timeout);
            }
            if (r.isSolved()) {
                // PDDL4J 3.8.3 sometimes reports wrong plans (its encoding can drop actions or goals)
                PlanValidator.Report report = PlanValidator.validate(domain, problem, r.plan());
                if (!report.valid()) return SolveResult.error("PDDL4J returned a plan that does not validate: " + report.message());
            }
            return r;
        } catch (IOException e) {
            return SolveResult.error("PDDL4J input could not be written: " + e.getMessage());
        } catch (RuntimeException | StackOverflowError e) {
            // PDDL4J crashes on some inputs (e.g. exists, when): report, never propagate
            return SolveResult.error("PDDL4J failed: " + e);
        } finally {
            if (dir != null) {
                dir.resolve("domain.pddl").toFile().delete();
                dir.resolve("problem.pddl").toFile().delete();
                dir.toFile().delete();
            }
        }
    }

    /** The fluents the task's conditions and effects compute with, beyond action costs ({@code (courier-battery)}), or "". */
    private static String numbers(Domain d, Problem p) {
        java.util.Set<String> names = new java.util.TreeSet<>();
        for (org.triad.planner.pddl.Action a : d.actions()) {
            org.triad.planner.pddl.NumericParts.fluents(a).forEach(f -> names.add("(" + f.name() + ")"));
        }
        if (org.triad.planner.pddl.NumericParts.isNumeric(p.goal())) {
            names.add("numbers in the goal");
        }
        return String.join(", ", names);
    }

    /**
     * The domain without its action costs ({@code (increase (total-cost) ...)}), its functions and the fluent
     * requirements, or the domain itself when it has no costs. PDDL4J 3.8.3 has no numeric fluents: a problem
     * whose only numbers are action costs (a hospital whose moves cost their length) is planned without them,
     * for the fewest steps; one with other numbers is handed over whole, and PDDL4J's error names them.
     */
    static Domain withoutCosts(Domain d) {
        boolean costed = false;
        List<org.triad.planner.pddl.Action> actions = new ArrayList<>();
        for (org.triad.planner.pddl.Action a : d.actions()) {
            List<org.triad.planner.pddl.PddlEffect> effects = new ArrayList<>();
            for (org.triad.planner.pddl.PddlEffect e : a.effects()) {
                if (e instanceof org.triad.planner.pddl.PddlEffect.Increase
                        || e instanceof org.triad.planner.pddl.PddlEffect.NumericEffect n && n.target().name().equals("total-cost")) {
                    costed = true;
                } else {
                    effects.add(e);
                }
            }
            actions.add(new org.triad.planner.pddl.Action(a.name(), a.parameters(), a.precondition(), effects));
        }
        if (!costed) {
            return d;
        }
        List<String> requirements = d.requirements().stream()
                .filter(r -> !List.of(":fluents", ":numeric-fluents", ":action-costs").contains(r)).toList();
        return new Domain(d.name(), requirements, d.types(), d.constants(), d.predicates(), List.of(), actions, d.axioms());
    }

    private SolveResult solveLocked(File d, File p, Duration timeout) throws IOException {
        long start = System.nanoTime();
        ProblemFactory factory = new ProblemFactory();
        factory.setTraceLevel(0);
        ErrorManager errors = factory.parse(d, p);
        List<String> messages = new ArrayList<>();
        for (Message.Type t : List.of(Message.Type.LEXICAL_ERROR, Message.Type.PARSER_ERROR)) {
            for (Message m : errors.getMessages(t)) messages.add(m.toString());
        }
        if (!messages.isEmpty()) return SolveResult.error("PDDL4J rejects the input: " + String.join("; ", messages));
        CodedProblem coded = factory.encode();
        double groundMs = (System.nanoTime() - start) / 1e6;
        if (!coded.isSolvable()) {
            return SolveResult.unsolvable("PDDL4J's encoding simplified the goal to false", new SolveResult.Stats(groundMs, 0, 0, 0));
        }
        long remainingMs = Math.max(1, timeout.toMillis() - (long) groundMs);
        // FF runs enforced hill-climbing and then greedy search, each with the full limit (measured:
        // a 10 s limit returned after 20 s), so each gets half of what remains
        if (search == Search.FF) remainingMs = Math.max(1, remainingMs / 2);
        int timeoutMs = (int) Math.min(Integer.MAX_VALUE, remainingMs);
        AbstractStateSpacePlanner planner = search == Search.FF
                ? new FF(timeoutMs, Heuristic.Type.FAST_FORWARD, 1.0, false, 0)
                : new HSP(timeoutMs, Heuristic.Type.FAST_FORWARD, 1.0, false, 0);
        long searchStart = System.nanoTime();
        fr.uga.pddl4j.util.Plan plan = planner.search(coded);
        double searchMs = (System.nanoTime() - searchStart) / 1e6;
        SolveResult.Stats stats = new SolveResult.Stats(groundMs, searchMs, 0, 0);
        if (plan == null) {
            // 3.8.3 returns null both when the search space is exhausted and on timeout
            double limit = search == Search.FF ? 2.0 * timeoutMs : timeoutMs;
            if (searchMs < 0.9 * limit) return SolveResult.unsolvable("PDDL4J's search ended without a plan", stats);
            return SolveResult.timeout(stats);
        }
        List<String> constants = coded.getConstants();
        List<PddlStep> steps = new ArrayList<>();
        for (BitOp op : plan.actions()) {
            List<String> args = new ArrayList<>(op.getArity());
            for (int i = 0; i < op.getArity(); i++) args.add(constants.get(op.getValueOfParameter(i)).toLowerCase(Locale.ROOT));
            steps.add(new PddlStep(op.getName().toLowerCase(Locale.ROOT), args));
        }
        return SolveResult.solved(new PddlPlan(steps), stats);
    }
}
