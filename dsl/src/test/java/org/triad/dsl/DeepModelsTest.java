package org.triad.dsl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;
import org.triad.dsl.parser.ExpressionLimits;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * The deep and large inputs of issue #15, generated at full size: a 10,000-term conjunction, 10,000
 * nested parentheses and 10,000 negations end in one {@code expr.too-deep} at the first token past
 * the limit (not a stack overflow, not a finding at 1:1), a conjunction at the limit checks clean,
 * and a multi-megabyte file of goals checks clean. How the time grows is measured by
 * {@code DeepModelsBenchmark}, not here.
 */
class DeepModelsTest {
	private static final String CALL = "Bot.holds(b)";

	@TempDir
	Path dir;

	@Test
	void tenThousandTermConjunctionStopsAtTheDepthLimit() throws IOException {
		String chain = String.join(" && ", java.util.Collections.nCopies(10_000, CALL));
		LoadedApplication app = load(goal(chain));
		// the operator after term MAX_DEPTH is the first one too many
		int column = 3 + ExpressionLimits.MAX_DEPTH * (CALL.length() + 4) - 3;
		assertOnlyTooDeep(app, 8, column);
	}

	@Test
	void conjunctionAtTheLimitChecksClean() throws IOException {
		String chain = String.join(" && ", java.util.Collections.nCopies(ExpressionLimits.MAX_DEPTH, CALL));
		LoadedApplication app = load(goal(chain));
		assertEquals(List.of(), app.diagnostics());
	}

	@Test
	void tenThousandNestedParenthesesStopAtTheNestingLimit() throws IOException {
		LoadedApplication app = load(goal("(".repeat(10_000) + CALL + ")".repeat(10_000)));
		// the first token inside the parenthesis that opens level MAX_NESTING + 1
		assertOnlyTooDeep(app, 8, 3 + ExpressionLimits.MAX_NESTING + 1);
	}

	@Test
	void tenThousandNegationsStopAtTheNestingLimit() throws IOException {
		LoadedApplication app = load(goal("!".repeat(10_000) + CALL));
		// the first '!' has no nesting below it; the one after the limit's is the first too deep
		ModelDiagnostic d = tooDeep(app);
		assertEquals(8, d.line(), d.format(dir));
		assertEquals(3 + ExpressionLimits.MAX_NESTING + 1, d.column(), d.format(dir));
	}

	@Test
	void deepCallArgumentsStopAtTheNestingLimit() throws IOException {
		// ill-typed (adj takes places), so the levels below the limit have their own findings; the one past it has expr.too-deep
		LoadedApplication app = load(goal("World.adj(".repeat(5_000) + "b" + ", b)".repeat(5_000)));
		List<ModelDiagnostic> tooDeep = app.diagnostics().stream().filter(d -> d.code().equals(CommonIssueCodes.EXPRESSION_TOO_DEEP)).toList();
		assertEquals(1, tooDeep.size(), tooDeep.toString());
		// the first token inside the call that opens level MAX_NESTING + 1
		assertEquals("8:" + (3 + (ExpressionLimits.MAX_NESTING + 1) * "World.adj(".length()), tooDeep.get(0).line() + ":" + tooDeep.get(0).column());
		assertTrue(app.diagnostics().size() < 3 * ExpressionLimits.MAX_NESTING, "findings: " + app.diagnostics().size());
	}

	/** Long sums (issue #22): typing, folding constants and finding quantities stay quadratic at most, not cubic. */
	@Test
	void longArithmeticChecksClean() throws IOException {
		String quantities = String.join(" + ", java.util.Collections.nCopies(ExpressionLimits.MAX_DEPTH / 2, "Bot.charge()"));
		String literals = String.join(" + ", java.util.Collections.nCopies(ExpressionLimits.MAX_DEPTH / 2, "1"));
		LoadedApplication app = load(goal("Bot.holds(b) && " + quantities + " > 0.5 && Bot.charge() < " + literals));
		assertEquals(List.of(), app.diagnostics());
	}

	@Test
	void multiMegabyteFileChecksClean() throws IOException {
		StringBuilder goals = new StringBuilder("domain Shop;\n");
		for (int i = 0; goals.length() < 2_000_000; i++) { // just under the 2 MiB a model file may have (file.too-large)
			goals.append("\ngoal Reach").append(i).append("(Place p, Box b) {\n  Bot.loc() == p && (Bot.holds(b) || !World.adj(p, p))\n}\n");
		}
		Files.writeString(dir.resolve("Many.goal"), goals);
		copyBase();
		LoadedApplication app = ApplicationAssembler.load(dir);
		assertEquals(List.of(), app.diagnostics());
		assertTrue(app.application().getGoals().size() > 15_000, "goals read: " + app.application().getGoals().size());
	}

	private static String goal(String condition) {
		// line 8 holds the condition, from column 3
		return "domain Shop;\n\ngoal At(Place p) {\n  Bot.loc() == p\n}\n\ngoal Holding(Box b) {\n  " + condition + "\n}\n";
	}

	private LoadedApplication load(String atGoal) throws IOException {
		copyBase();
		Files.writeString(dir.resolve("At.goal"), atGoal);
		return ApplicationAssembler.load(dir);
	}

	private void copyBase() throws IOException {
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				if (!Files.exists(dir.resolve(f.getFileName()))) {
					Files.copy(f, dir.resolve(f.getFileName()));
				}
			}
		}
	}

	private ModelDiagnostic tooDeep(LoadedApplication app) {
		List<ModelDiagnostic> errors = app.diagnostics().stream().filter(ModelDiagnostic::isError).toList();
		assertEquals(1, errors.size(), () -> errors.stream().map(d -> d.format(dir)).toList().toString());
		ModelDiagnostic d = errors.get(0);
		assertEquals(CommonIssueCodes.EXPRESSION_TOO_DEEP, d.code(), d.format(dir));
		assertEquals("At.goal", dir.relativize(d.file()).toString());
		return d;
	}

	private void assertOnlyTooDeep(LoadedApplication app, int line, int column) {
		ModelDiagnostic d = tooDeep(app);
		assertEquals(line + ":" + column, d.line() + ":" + d.column(), d.format(dir));
	}
}
