package org.triad.dsl.rules;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.ModelDiagnostic;

/** The words of the findings about conditions: they name the operand, what it is, and how to write it. */
class ConditionMessagesTest {
	@TempDir
	Path dir;

	private List<String> messages(String code) throws Exception {
		new RuleCase(code, "bad", RuleCase.RULES.resolve(code).resolve("bad")).materialize(dir);
		return ApplicationAssembler.load(dir).diagnostics().stream().filter(d -> d.code().equals(code)).map(ModelDiagnostic::message)
				.toList();
	}

	@Test
	void aNumberOrAnObjectWhereAConditionBelongsIsNamed() throws Exception {
		assertEquals(List.of("'charge()' is a double, not a condition (true or false): '&&' joins conditions; compare it, e.g. 'charge() > 0'",
				"'loc()' is a Place, not a condition (true or false): '!' negates a condition; compare it, e.g. 'loc() == value'"),
				messages("expr.not-boolean"));
	}

	@Test
	void aConditionPassedAsAnArgumentSaysHowToPassIt() throws Exception {
		assertEquals(java.util.Set.of("'handEmpty()' is a condition and cannot be the argument of 'ready': the planner passes objects and values only;"
				+ " give the action or goal a boolean parameter b, pass b, and require 'handEmpty() == b'",
				"'Bot.handEmpty()' is a condition and cannot be the argument of 'ready': the planner passes objects and values only;"
						+ " give the action or goal a boolean parameter b, pass b, and require 'Bot.handEmpty() == b'"),
				java.util.Set.copyOf(messages("plan.condition-as-argument")));
		assertEquals(true, Files.exists(dir.resolve("Bot.actor")));
	}
}
