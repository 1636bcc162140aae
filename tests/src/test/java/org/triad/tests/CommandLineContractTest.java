package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.triad.cli.TriadCli;

import picocli.CommandLine;

/**
 * What the README promises of the command line: every command answers {@code --help}, every option
 * the README shows works, configuration errors are refused at start-up with one line and exit 2, and
 * an output folder that cannot be used is named with the reason.
 */
class CommandLineContractTest {
	record Run(int exit, String out, String err) {
	}

	static Run run(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int exit = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Run(exit, out.toString(), err.toString());
	}

	private String home;

	/** The checkout whose built models/hospital the demo runs from (the CLI depends on no example). */
	@BeforeEach
	void triadHomeIsTheCheckout() {
		home = System.getProperty("triad.home");
		System.setProperty("triad.home", "..");
	}

	@AfterEach
	void restore() {
		if (home == null) {
			System.clearProperty("triad.home");
		} else {
			System.setProperty("triad.home", home);
		}
	}

	private static final String HOSPITAL = "../models/hospital/src/main/models";

	@TempDir
	Path tmp;

	@Test
	void everyCommandAnswersHelp() {
		CommandLine cli = new CommandLine(new TriadCli());
		List<String> commands = cli.getSubcommands().keySet().stream().filter(c -> !c.equals("help")).toList();
		assertTrue(commands.containsAll(List.of("demo", "check", "generate", "run", "pddl", "solve", "lsp")), commands.toString());
		for (String command : commands) {
			Run run = run(command, "--help");
			assertEquals(0, run.exit(), command + " --help: " + run.err());
			assertTrue(run.out().startsWith("Usage: triad " + command), command + " --help:\n" + run.out());
		}
	}

	@Test
	void theReadmesCheckGeneratePddlAndSolveOptionsWork() throws IOException {
		Run generate = run("generate", HOSPITAL, "-o", tmp.resolve("java").toString(), "-p", "org.example.hospital");
		assertEquals(0, generate.exit(), generate.err());
		assertTrue(Files.isRegularFile(tmp.resolve("java/org/example/hospital/IRobot.java")));
		Run pddl = run("pddl", HOSPITAL, "--state", "Morning.state", "--goal", "IsAt(ward3)", "-o", tmp.resolve("pddl").toString());
		assertEquals(0, pddl.exit(), pddl.err());
		assertTrue(Files.readString(tmp.resolve("pddl/problem.pddl")).contains("(:goal"));
		Run solve = run("solve", tmp.resolve("pddl/domain.pddl").toString(), tmp.resolve("pddl/problem.pddl").toString(), "-o",
				tmp.resolve("plan.txt").toString());
		assertEquals(0, solve.exit(), solve.err());
		assertTrue(Files.readString(tmp.resolve("plan.txt")).strip().startsWith("("), Files.readString(tmp.resolve("plan.txt")));
		Run check = run("check", HOSPITAL);
		assertEquals(0, check.exit(), check.out() + check.err());
	}

	@Test
	void failIsRepeatableAndEveryInjectedFailureHappens() {
		Run run = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--fail", "move@1", "--fail",
				"move@2", "--fail", "move@4");
		assertEquals(0, run.exit(), run.out() + run.err());
		List<String> replans = run.out().lines().filter(l -> l.startsWith("replanning")).toList();
		assertEquals(List.of("(1 of 3)", "(2 of 3)", "(1 of 3)"), replans.stream().map(l -> l.replaceAll(".*(\\(\\d of 3\\)).*", "$1")).toList(),
				"move 3 succeeds between the failures of moves 2 and 4, so the count starts again:\n" + run.out());
	}

	@Test
	void fourFailuresInARowAbort() {
		Run run = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--fail", "move@1", "--fail",
				"move@2", "--fail", "move@3", "--fail", "move@4");
		assertEquals(1, run.exit(), run.out() + run.err());
		assertTrue(run.out().lines().anyMatch(l -> l.startsWith("task GoTo(ward3) aborted at goal IsAt(ward3): action Courier.move")), run.out());
	}

	@Test
	void configurationErrorsAreRefusedAtStartUp() {
		Run timeout = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--planning-timeout", "-1");
		assertEquals(2, timeout.exit());
		assertEquals("", timeout.out());
		assertEquals("triad run: --planning-timeout takes a time in seconds > 0, not -1.0", timeout.err().strip());

		Run planner = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--planner",
				"no-such-planner-xyz {domain} {problem} {plan}");
		assertEquals(2, planner.exit());
		assertEquals("", planner.out());
		assertEquals("triad run: --planner: cannot run 'no-such-planner-xyz': not found on PATH", planner.err().strip());

		Run path = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--planner",
				tmp.resolve("missing/planner") + " {domain} {problem}");
		assertEquals(2, path.exit());
		assertTrue(path.err().strip().endsWith(": no such executable file"), path.err());

		Run nth = run("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--fail", "move@0");
		assertEquals(2, nth.exit());
		assertEquals("triad run: --fail: calls are counted from 1, not 0 in 'move@0'", nth.err().strip());

		Run seed = run("demo", "--seed", "many");
		assertEquals(2, seed.exit());
		assertTrue(seed.err().contains("--seed"), seed.err());
	}

	@Test
	void anOutputFolderThatIsAFileIsRefusedWithTheReason() throws IOException {
		Path file = Files.writeString(tmp.resolve("taken"), "not a folder");
		for (String[] args : List.of(new String[] { "generate", HOSPITAL, "-o", file.toString() },
				new String[] { "pddl", HOSPITAL, "--state", "Morning.state", "--goal", "IsAt(ward3)", "-o", file.toString() },
				new String[] { "demo", "-o", file.toString() })) {
			Run run = run(args);
			assertEquals(2, run.exit(), args[0] + ": " + run.out() + run.err());
			assertEquals("triad " + args[0] + ": -o " + file + ": not a folder (a file of that name exists)", run.err().strip());
			assertEquals("", run.out(), args[0] + " did no work before refusing");
		}
		Run below = run("generate", HOSPITAL, "-o", file.resolve("java").toString());
		assertEquals(2, below.exit());
		assertEquals("triad generate: -o " + file.resolve("java") + ": cannot create the folder: " + file.toAbsolutePath().normalize()
				+ " exists and is not a folder", below.err().strip());
	}
}
