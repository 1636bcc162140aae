package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The {@code triad} command line as a user meets it: exit codes, findings, help. */
class TriadCliTest {
	record Run(int exit, String out, String err) {
	}

	static Run run(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int exit = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Run(exit, out.toString(), err.toString());
	}

	@ParameterizedTest
	@ValueSource(strings = { "hospital", "logistics" })
	void checkOfAnExampleApplicationIsSilentAndSucceeds(String name) {
		Run run = run("check", Path.of("..", "models", name, "src", "main", "models").toString());
		assertEquals(new Run(0, "", ""), run);
	}

	/** The README's own example: the application folder, whose architecture links against RefArc's models in the refarc jar. */
	@ParameterizedTest
	@ValueSource(strings = { "hospital", "logistics" })
	void checkOfAnApplicationFolderWithItsArchitectureSucceeds(String name) {
		assertEquals(new Run(0, "", ""), run("check", Path.of("..", "models", name).toString()));
	}

	@Test
	void checkOfABadApplicationPrintsFindingsRelativeToTheFolderAndFails(@TempDir Path dir) throws IOException {
		Path logistics = Path.of("..", "models", "logistics", "src", "main", "models");
		try (Stream<Path> files = Files.list(logistics)) {
			for (Path f : files.toList()) {
				Files.copy(f, dir.resolve(f.getFileName()));
			}
		}
		Files.createDirectories(dir.resolve("goals"));
		Files.writeString(dir.resolve("goals").resolve("Near.goal"), """
				domain LogisticsDomain;

				goal Near(WayPoint wp, Room r) {
				  Robot.loc() == wp
				}
				""");
		Run run = run("check", dir.toString());
		assertEquals(1, run.exit());
		assertEquals("""
				goals/Near.goal:3:29: warning goal.unused-parameter: parameter 'r' of goal 'Near' is not used
				goals/Near.goal:4:3: error link.unknown-actor: unknown actor 'Robot'
				""", run.out().replace(System.lineSeparator(), "\n").replace('\\', '/'));
		assertEquals("", run.err());
	}

	@Test
	void checkWithOnlyWarningsSucceeds(@TempDir Path dir) throws IOException {
		Path logistics = Path.of("..", "models", "logistics", "src", "main", "models");
		try (Stream<Path> files = Files.list(logistics)) {
			for (Path f : files.toList()) {
				Files.copy(f, dir.resolve(f.getFileName()));
			}
		}
		Files.writeString(dir.resolve("Idle.task"), "domain LogisticsDomain;\n\ntask Idle() {\n}\n");
		Run run = run("check", dir.toString());
		assertEquals(new Run(0, "Idle.task:3:6: warning task.empty: task 'Idle' has no goals" + System.lineSeparator(), ""), run);
	}

	@Test
	void checkOfAMissingFolderFailsWithOneLine(@TempDir Path dir) {
		Path missing = dir.resolve("nowhere");
		Run run = run("check", missing.toString());
		assertEquals(2, run.exit());
		assertEquals("", run.out());
		assertEquals("triad check: not a folder: " + missing + System.lineSeparator(), run.err());
	}

	@Test
	void helpListsTheCommands() {
		Run run = run("--help");
		assertEquals(0, run.exit());
		assertEquals("", run.err());
		assertTrue(run.out().contains("Usage: triad"), run.out());
		for (String command : new String[] { "check", "lsp", "help" }) {
			assertTrue(run.out().lines().anyMatch(l -> l.trim().startsWith(command + " ") || l.trim().equals(command)),
					command + " is listed in:\n" + run.out());
		}
	}

	@Test
	void unknownCommandIsAUsageError() {
		Run run = run("frobnicate");
		assertEquals(2, run.exit());
		assertTrue(run.err().contains("frobnicate"), run.err());
	}
}
