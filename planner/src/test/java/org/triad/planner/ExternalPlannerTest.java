package org.triad.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.Problem;

/** Runs fake planner scripts that print known plans; no real planner is needed. */
class ExternalPlannerTest {
    @TempDir
    Path dir;

    private final Domain domain = TestProblems.domain("hospital/domain.pddl");
    private final Problem problem = TestProblems.problem("hospital/p-10-a.pddl");

    private Path script(String name, String body) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, "#!/bin/sh\n" + body);
        Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rwxr-xr-x"));
        return p;
    }

    @Test
    void readsAPlanFileInParenthesisedForm() throws IOException {
        // checks it was handed readable domain and problem files, then writes the plan file
        Path s = script("fd.sh", """
                grep -q '(define (domain hospital)' "$3" || exit 3
                grep -q '(robot-at wp0)' "$4" || exit 4
                printf '(move wp0 wp3)\\n(MOVE wp3 wp6)\\n(move wp6 r1)\\n; cost = 3 (unit cost)\\n' > "$2"
                echo 'Solution found.'
                """);
        ExternalPlanner p = new ExternalPlanner("fake-fd", s + " --plan-file {plan} {domain} {problem}");
        SolveResult r = p.solve(domain, problem, Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.SOLVED, r.status(), r.message());
        assertEquals(List.of(PddlStep.of("move", "wp0", "wp3"), PddlStep.of("move", "wp3", "wp6"), PddlStep.of("move", "wp6", "r1")),
                r.plan().steps());
        assertTrue(PlanValidator.validate(domain, problem, r.plan()).valid());
    }

    @Test
    void readsFfStepsFromStandardOutput() throws IOException {
        Path s = script("ff.sh", """
                echo 'ff: parsing domain file'
                echo 'ff: found legal plan as follows'
                echo ''
                echo 'step    0: MOVE WP0 WP3'
                echo '        1: MOVE WP3 WP6'
                echo '        2: MOVE WP6 R1'
                echo ''
                echo 'time spent:    0.00 seconds instantiating 22 easy, 0 hard action templates'
                """);
        SolveResult r = new ExternalPlanner("fake-ff", s + " -o {domain} -f {problem}").solve(domain, problem, Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.SOLVED, r.status(), r.message());
        assertEquals(PddlStep.of("move", "wp6", "r1"), r.plan().steps().get(2));
        assertEquals(3, r.plan().length());
    }

    @Test
    void mapsUnsolvableTimeoutAndFailures() throws IOException {
        Path unsolvable = script("u.sh", "echo 'ff: goal can be simplified to FALSE. No plan will solve it'; echo 'problem proven unsolvable'\n");
        assertEquals(SolveResult.Status.UNSOLVABLE,
                new ExternalPlanner("u", unsolvable.toString()).solve(domain, problem, Duration.ofSeconds(10)).status());
        Path slow = script("slow.sh", "sleep 30\n");
        long t0 = System.nanoTime();
        assertEquals(SolveResult.Status.TIMEOUT, new ExternalPlanner("slow", slow.toString()).solve(domain, problem, Duration.ofMillis(300)).status());
        assertTrue((System.nanoTime() - t0) / 1e9 < 10, "the planner process must be killed at the timeout");
        Path crash = script("crash.sh", "echo 'segmentation fault' >&2; exit 139\n");
        SolveResult r = new ExternalPlanner("crash", crash.toString()).solve(domain, problem, Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.ERROR, r.status());
        assertTrue(r.message().contains("exited with status 139") && r.message().contains("segmentation fault"), r.message());
        SolveResult missing = new ExternalPlanner("none", dir.resolve("no-such-planner") + " {domain}").solve(domain, problem, Duration.ofSeconds(10));
        assertEquals(SolveResult.Status.ERROR, missing.status());
        assertTrue(missing.message().startsWith("cannot start planner"), missing.message());
    }

    @Test
    void parsesTimeStampedPlans() {
        PddlPlan p = ExternalPlanner.parsePlan("; comment\n0.000: (move wp0 wp1) [1]\n1.000: (move wp1 wp2) [1]\n");
        assertEquals(List.of(PddlStep.of("move", "wp0", "wp1"), PddlStep.of("move", "wp1", "wp2")), p.steps());
    }
}
