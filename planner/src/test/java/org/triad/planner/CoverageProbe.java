package org.triad.planner;

import java.nio.file.Path;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Timestamps and counters of the phases to a first plan, without a profiler:
 * {@code CoverageProbe PROBLEM SECONDS [lazy|lazyff|eager|waW:BOUND:EVALS|trace PLAN_FILE]} (domain found as Fast
 * Downward's driver finds it; {@code -Dadditive} uses {@link AdditiveFfHeuristic}). Prints parse,
 * grounding, relevance and landmark times and sizes, then one search's outcome, expansions,
 * evaluations and evaluations per second; {@code trace} prints h, the landmark count and whether
 * the next action is helpful along a given plan (e.g. Fast Downward's). See planner/BENCHMARK.md.
 */
public final class CoverageProbe {
    public static void main(String[] args) throws Exception {
        Path pf = Path.of(args[0]);
        long t0 = System.nanoTime();
        Domain d = PddlParser.parseDomain(IpcCorpusCheck.domainOf(pf));
        Problem p = PddlParser.parseProblem(pf);
        long t1 = System.nanoTime();
        GroundedProblem gp = new GroundedProblem(d, p);
        GroundedProblem.Query q = gp.query(p);
        long t2 = System.nanoTime();
        System.out.printf("parse %.2f s, ground %.2f s: %d facts, %d ops%n", (t1 - t0) / 1e9, (t2 - t1) / 1e9, gp.factCount(), gp.actionCount());
        SearchTask task = q.task().relevantTo(q.goalPos(), q.goalNeg());
        FfHeuristic h = System.getProperty("additive") != null ? new AdditiveFfHeuristic(task) : new FfHeuristic(task);
        Successors succ = new Successors(task);
        long t3 = System.nanoTime();
        System.out.printf("relevant %.2f s: %d ops, goals %d, h0 = %d%n", (t3 - t2) / 1e9, task.ops.length, q.goalPos().length, h.evaluate(q.init(), q.goalPos()));
        long deadline = System.nanoTime() + (long) (Double.parseDouble(args[1]) * 1e9);
        Landmarks lms = new Landmarks(task, q.init(), q.goalPos(), deadline);
        long t4 = System.nanoTime();
        System.out.printf("landmarks %.2f s: %d%n", (t4 - t3) / 1e9, lms.count);
        String mode = args.length > 2 ? args[2] : "lazy";
        if (mode.equals("trace")) {
            // the heuristic along a given plan (e.g. Fast Downward's): where it misleads
            int[] state = q.init();
            for (String line : java.nio.file.Files.readAllLines(Path.of(args[3]))) {
                if (!line.startsWith("(")) continue;
                String step = line.substring(1, line.length() - 1).trim().toLowerCase();
                int op = -1;
                for (int o = 0; o < task.ops.length; o++) {
                    if ((task.ops[o].name() + " " + String.join(" ", task.ops[o].args())).toLowerCase().equals(step)) op = o;
                }
                int hv = h.evaluate(state, q.goalPos());
                int nh = h.helpfulCount();
                boolean helpful = false;
                for (int i = 0; i < nh; i++) helpful |= h.helpful(i) == op;
                System.out.printf("h = %d, lm = %d, %d helpful, next %s (%s)%n", hv, lms.value(lms.accept(null, state), state), nh, step,
                        op < 0 ? "NOT GROUND" : helpful ? "helpful" : "not helpful");
                if (op < 0) return;
                state = succ.apply(state, op);
            }
            System.out.printf("h = %d at the end, goal %s%n", h.evaluate(state, q.goalPos()), Successors.satisfies(state, q.goalPos(), q.goalNeg()));
            return;
        }
        BestFirstSearch.Result r;
        if (mode.equals("lazy")) {
            r = new LazyGreedySearch(h, lms, succ, deadline).run(q.init(), q.goalPos(), q.goalNeg());
        } else if (mode.startsWith("wa")) {
            // waW:BOUND:EVALS weighted A* looking for plans shorter than BOUND
            String[] m = mode.split(":");
            r = new BestFirstSearch(task, h, succ, deadline).boundLength(Integer.parseInt(m[1]))
                    .run(q.init(), q.goalPos(), q.goalNeg(), 1, Integer.parseInt(m[0].substring(2)), true, Long.parseLong(m[2]));
        } else if (mode.equals("lazyff")) {
            r = new LazyGreedySearch(h, null, succ, deadline).run(q.init(), q.goalPos(), q.goalNeg());
        } else {
            r = new BestFirstSearch(task, h, succ, deadline).run(q.init(), q.goalPos(), q.goalNeg(), 0, 1, true, Long.MAX_VALUE);
        }
        long t5 = System.nanoTime();
        System.out.printf("%s %.2f s: %s, expanded %d, evaluated %d, length %s, %.0f evals/s%n", mode, (t5 - t4) / 1e9, r.outcome(), r.expanded(), r.evaluated(),
                r.plan() == null ? "-" : r.plan().length, r.evaluated() / ((t5 - t4) / 1e9));
    }
}
