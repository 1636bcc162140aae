package org.triad.runtime.planning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SolveCommandTest {
    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return SolveCommand.run(List.of(args), new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private Path copy(String resource) throws IOException {
        Path p = dir.resolve(resource.replace('/', '_'));
        Files.writeString(p, TestProblems.text(resource));
        return p;
    }

    @Test
    void printsAPlanVALReadsAndWritesThePlanFile() throws IOException {
        Path plan = dir.resolve("plan.txt");
        int code = run(copy("hospital/domain.pddl").toString(), copy("hospital/p-10-a.pddl").toString(), "-o", plan.toString(), "--timeout", "20");
        assertEquals(0, code, err.toString());
        String text = out.toString(StandardCharsets.UTF_8);
        List<String> lines = new ArrayList<>(text.lines().toList());
        assertEquals("; cost = 3 (unit cost)", lines.get(lines.size() - 1));
        assertTrue(lines.get(0).matches("\\(move wp0 \\S+\\)"), lines.get(0));
        assertEquals(text, Files.readString(plan));
    }

    @Test
    void exitsOneWithoutAPlan() throws IOException {
        Path problem = dir.resolve("island.pddl");
        Files.writeString(problem, "(define (problem island) (:domain hospital) (:objects a b - waypoint)"
                + " (:init (robot-at a) (hand-empty)) (:goal (robot-at b)))");
        assertEquals(1, run(copy("hospital/domain.pddl").toString(), problem.toString()));
        assertTrue(err.toString().startsWith("no plan: problem is unsolvable"), err.toString());
    }

    @Test
    void exitsTwoOnUsageAndInputErrors() throws IOException {
        assertEquals(2, run("only-one.pddl"));
        assertTrue(err.toString().contains("usage: solve DOMAIN.pddl PROBLEM.pddl"));
        err.reset();
        assertEquals(2, run("a.pddl", "b.pddl", "--planner", "metric-ff"));
        assertTrue(err.toString().contains("unknown planner 'metric-ff'"), err.toString());
        err.reset();
        assertEquals(2, run(dir.resolve("missing.pddl").toString(), "b.pddl"));
        assertTrue(err.toString().startsWith("error: no such file: "), err.toString());
        err.reset();
        Path bad = dir.resolve("bad.pddl");
        Files.writeString(bad, "(define (domain d)\n  (:predicates (p))\n  (:action a :parameters () :effect (q)))\n");
        assertEquals(2, run(bad.toString(), copy("hospital/p-10-a.pddl").toString()));
        assertTrue(err.toString().startsWith("error: " + bad + ":3:3: action 'a' uses undeclared predicate 'q'"), err.toString());
        err.reset();
        assertEquals(2, run("a.pddl", "b.pddl", "--timeout", "soon"));
        assertTrue(err.toString().contains("--timeout expects seconds"));
    }
}
