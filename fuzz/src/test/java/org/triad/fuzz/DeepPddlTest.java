package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.triad.planner.PddlPlanners;
import org.triad.planner.SolveResult;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

/**
 * Issue #15's deep PDDL input at full size: a goal nesting 20,000 {@code (and} (the blocks problem
 * of the IPC set) ends in a plan or a located parse error, as {@code ./triad solve} reads it, not
 * in a stack overflow. Generated here rather than kept in {@link PddlFuzzTest}'s corpus (100 KB).
 */
class DeepPddlTest {
	private static final Path BLOCKS = Path.of("..", "planner", "src", "test", "resources", "pddl", "ipc", "blocks");

	@Test
	void twentyThousandNestedAndsEndInAPlanOrALocatedError() throws IOException {
		Domain domain = PddlParser.parseDomain(Files.readString(BLOCKS.resolve("domain.pddl")), "domain.pddl");
		String problem = Files.readString(BLOCKS.resolve("probBLOCKS-4-0.pddl"));
		String deepGoal = "(:goal " + "(and ".repeat(20_000) + "(ON D C) (ON C B) (ON B A)" + ")".repeat(20_000) + ")";
		problem = problem.replace("(:goal (AND (ON D C) (ON C B) (ON B A)))", deepGoal);
		assertTrue(problem.contains("(and (and"), "the goal was replaced");
		Problem parsed;
		try {
			parsed = PddlParser.parseProblem(problem, "problem.pddl");
		} catch (PddlParseException e) {
			assertTrue(e.line() >= 1 && e.column() >= 1, e.getMessage());
			return;
		}
		SolveResult result = PddlPlanners.byName("triad").solve(domain, parsed, Duration.ofSeconds(10));
		assertNotEquals(SolveResult.Status.ERROR, result.status(), result.message());
	}
}
