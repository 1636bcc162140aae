package org.triad.pddl4j;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.PddlWriter;
import org.triad.planner.SolveResult;
import org.triad.planner.SolveResult.Status;
import org.triad.planner.PlanValidator;
import org.triad.planner.TriadEngine;

/**
 * Triad's engine against PDDL4J on seeded random typed STRIPS tasks with negative preconditions and
 * equality: every plan of either must validate; where both decide, they must agree on solvability.
 * PDDL4J timeouts and crashes are counted and printed, not hidden.
 */
class DifferentialIT {
    private static final int TASKS = Integer.getInteger("triad.differential.tasks", 2000);
    /** PDDL4J's FF does not stop early on unsolvable tasks: a short limit keeps the test fast. */
    private static final long PDDL4J_TIMEOUT_MS = 100;

    @Test
    void engineAndPddl4jAgree() {
        RandomProblems gen = new RandomProblems(20261122L);
        Pddl4jPlanner pddl4j = new Pddl4jPlanner();
        int bothSolved = 0;
        int bothUnsolvable = 0;
        int pddl4jUndecided = 0;
        int pddl4jErrors = 0;
        int triadOnlySolved = 0;
        int pddl4jInvalid = 0;
        String firstInvalid = null;
        List<String> failures = new ArrayList<>();
        long start = System.nanoTime();
        for (int i = 0; i < TASKS; i++) {
            RandomProblems.Task t = gen.next();
            SolveResult ours = new TriadEngine().solve(t.domain(), t.problem(), Duration.ofSeconds(5));
            SolveResult theirs = pddl4j.solve(t.domain(), t.problem(), Duration.ofMillis(PDDL4J_TIMEOUT_MS));
            String label = "task " + i + "\n" + PddlWriter.write(t.domain()) + PddlWriter.write(t.problem());
            if (ours.status() != Status.SOLVED && ours.status() != Status.UNSOLVABLE) {
                failures.add(label + "\ntriad: " + ours.status() + " " + ours.message());
                continue;
            }
            if (ours.isSolved()) {
                PlanValidator.Report r = PlanValidator.validate(t.domain(), t.problem(), ours.plan());
                if (!r.valid()) failures.add(label + "\ntriad plan invalid: " + r.message() + "\n" + ours.plan().toPddl());
            }
            if (theirs.isSolved()) {
                PlanValidator.Report r = PlanValidator.validate(t.domain(), t.problem(), theirs.plan());
                if (!r.valid()) {
                    // a PDDL4J defect, not ours: counted and shown, and this task is not compared
                    if (pddl4jInvalid++ == 0) firstInvalid = label + "\npddl4j plan invalid: " + r.message() + "\n" + theirs.plan().toPddl();
                    continue;
                }
            }
            switch (theirs.status()) {
                case SOLVED -> {
                    if (ours.isSolved()) bothSolved++;
                    else failures.add(label + "\ntriad says unsolvable, pddl4j found " + theirs.plan().toPddl());
                }
                case UNSOLVABLE -> {
                    if (ours.isSolved()) triadOnlySolved++; // PDDL4J's null result is no proof; our plan validated
                    else bothUnsolvable++;
                }
                case TIMEOUT -> pddl4jUndecided++;
                default -> {
                    if (theirs.message().contains("does not validate")) {
                        if (pddl4jInvalid++ == 0) firstInvalid = label + "\n" + theirs.message();
                    } else {
                        pddl4jErrors++;
                    }
                }
            }
        }
        System.out.printf("differential: %.1f s, %d tasks, both solved %d, both unsolvable %d, only triad solved %d, "
                + "pddl4j timeouts %d, pddl4j errors %d, pddl4j invalid plans %d%n", (System.nanoTime() - start) / 1e9, TASKS, bothSolved, bothUnsolvable, triadOnlySolved,
                pddl4jUndecided, pddl4jErrors, pddl4jInvalid);
        if (firstInvalid != null) System.out.println("first invalid PDDL4J plan:\n" + firstInvalid);
        assertEquals(List.of(), failures.subList(0, Math.min(3, failures.size())), failures.size() + " failures");
        assertTrue(bothSolved > TASKS / 10 && bothUnsolvable > TASKS / 10, "the generator must produce both outcomes");
        // PDDL4J 3.8.3 returns wrong plans on some tasks (its encoding drops actions, e.g. one whose
        // only effect is (p0 ?v1 ?v1) with an unused parameter ?v0, and FF then reports an
        // unrelated one-step plan as a solution): those are counted above and not compared.
        assertTrue(pddl4jErrors + pddl4jUndecided + pddl4jInvalid < TASKS / 4, "PDDL4J decided too few tasks to compare");
    }
}
