package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.time.Duration;

import org.triad.planner.PddlPlanners;
import org.triad.planner.SolveResult;
import org.triad.planner.pddl.Domain;
import org.triad.planner.pddl.PddlParseException;
import org.triad.planner.pddl.PddlParser;
import org.triad.planner.pddl.Problem;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * The PDDL reader and Triad's planning engine (grounding and search) through the path
 * {@code ./triad solve} takes: any domain and problem text ends in a located parse error or a
 * {@link SolveResult} that is not an internal error, within a time bound. The input is the domain,
 * a NUL byte, and the problem; seeds are the planner's hospital and IPC problems and the inputs that
 * found bugs ({@code src/test/resources/org/triad/fuzz/PddlFuzzTestInputs/domainAndProblem/}).
 */
class PddlFuzzTest {
	/** The engine's own time limit; grounding has none, so the whole call is bounded separately. */
	private static final Duration SEARCH_LIMIT = Duration.ofSeconds(2);
	private static final long BOUND_MS = 30_000;

	@FuzzTest(maxDuration = "10m")
	void domainAndProblem(byte[] input) {
		String text = new String(input, StandardCharsets.UTF_8);
		int nul = text.indexOf('\0');
		String domainText = nul < 0 ? text : text.substring(0, nul);
		String problemText = nul < 0 ? "" : text.substring(nul + 1);
		Domain domain;
		Problem problem;
		try {
			domain = PddlParser.parseDomain(domainText, "domain.pddl");
		} catch (PddlParseException e) {
			assertLocated(e, domainText, "domain.pddl");
			return;
		}
		try {
			problem = PddlParser.parseProblem(problemText, "problem.pddl");
		} catch (PddlParseException e) {
			assertLocated(e, problemText, "problem.pddl");
			return;
		}
		long start = System.nanoTime();
		SolveResult result = PddlPlanners.byName("triad").solve(domain, problem, SEARCH_LIMIT);
		long ms = (System.nanoTime() - start) / 1_000_000;
		assertNotNull(result);
		assertTrue(ms < BOUND_MS, "solving took " + ms + " ms");
		if (result.status() == SolveResult.Status.ERROR && result.message().startsWith("internal error")) {
			fail("the engine failed inside: " + result.message());
		}
	}

	private static void assertLocated(PddlParseException e, String text, String source) {
		long lines = text.chars().filter(c -> c == '\n').count() + 1;
		if (!source.equals(e.source()) || e.line() < 1 || e.column() < 1 || e.line() > lines) {
			fail("a parse error without its place in " + source + " (" + lines + " lines): " + e.getMessage());
		}
		if (e.detail() == null || e.detail().isBlank()) {
			fail("a parse error without a message: " + e.getMessage());
		}
	}
}
