package org.triad.dsl.rules;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.app.ModelDiagnostic;

/**
 * Runs every case below {@code src/test/resources/rules}: a {@code bad*} case must produce exactly
 * the diagnostics its {@code // expect:} comments announce (file, line, column where given,
 * severity, code) and nothing else; a {@code good*} case must produce no diagnostic at all.
 */
class RuleCasesTest {

	@TestFactory
	Stream<DynamicTest> everyRuleCase() {
		return RuleCase.all().stream().map(c -> DynamicTest.dynamicTest(c.toString(), () -> check(c)));
	}

	static void check(RuleCase c) throws IOException {
		Path dir = Files.createTempDirectory("triad-rule-");
		try {
			c.materialize(dir);
			List<RuleCase.Expectation> expected = c.expectations();
			if (c.isBad()) {
				assertFalse(expected.isEmpty(), c + ": a bad case needs at least one '// expect:' comment");
				assertTrue(expected.stream().anyMatch(e -> e.code().equals(c.code())),
						c + ": a bad case must expect its own code " + c.code());
			} else {
				assertTrue(expected.isEmpty(), c + ": a good case expects nothing");
			}
			LoadedApplication app = ApplicationAssembler.load(dir);
			List<ModelDiagnostic> unexpected = new ArrayList<>(app.diagnostics());
			List<RuleCase.Expectation> missing = new ArrayList<>();
			for (RuleCase.Expectation e : expected) {
				ModelDiagnostic hit = unexpected.stream().filter(d -> e.matches(d, app.root())).findFirst().orElse(null);
				if (hit == null) {
					missing.add(e);
				} else {
					unexpected.remove(hit);
				}
			}
			if (!missing.isEmpty() || !unexpected.isEmpty()) {
				fail(c + ":\n  missing:    " + missing + "\n  unexpected: "
						+ unexpected.stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n              "))
						+ "\n  all:        "
						+ app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n              ")));
			}
		} finally {
			try (Stream<Path> files = Files.walk(dir)) {
				for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
					Files.deleteIfExists(p);
				}
			}
		}
	}
}
