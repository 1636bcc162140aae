package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launcher's entry {@link TriadMain} answers {@code solve} as {@link TriadCli} does (output, errors,
 * exit codes), whether it plans without picocli or hands the command line on; each case runs both
 * entries as processes, TriadMain on the part of the class path the launcher gives {@code solve}.
 */
class TriadMainTest {
	private static final Path GRIPPER = Path.of("..", "planner", "src", "test", "resources", "pddl", "ipc", "gripper");
	private static final String DOMAIN = GRIPPER.resolve("domain.pddl").toString();
	private static final String PROBLEM = GRIPPER.resolve("prob01.pddl").toString();
	private static final String CLASS_PATH = System.getProperty("java.class.path");

	@TempDir
	Path dir;

	record Run(int exit, String out, String err) {
	}

	/** The main class in a JVM of its own, on the given class path (and the whole one named as the launcher names it). */
	private static Run java(String classPath, String mainClass, String... args) throws IOException, InterruptedException {
		List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
				"-XX:TieredStopAtLevel=1", "-Xshare:auto", "-D" + TriadMain.CLASS_PATH + "=" + CLASS_PATH, "-cp", classPath, mainClass));
		command.addAll(Arrays.asList(args));
		Process p = new ProcessBuilder(command).start();
		p.getOutputStream().close();
		byte[] out = p.getInputStream().readAllBytes();
		byte[] err = p.getErrorStream().readAllBytes();
		assertTrue(p.waitFor(60, TimeUnit.SECONDS), "exited");
		return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
	}

	/** This module's classes and the planner's, as the launcher's {@code solve} class path has them. */
	private static String cliAndPlanner() {
		String cli = Path.of("target", "classes").toAbsolutePath().toString();
		String planner = Arrays.stream(CLASS_PATH.split(File.pathSeparator))
				.filter(e -> e.contains("triad-planner-") || e.replace('\\', '/').endsWith("planner/target/classes"))
				.findFirst().orElseThrow(() -> new AssertionError("no planner on the test class path " + CLASS_PATH));
		return cli + File.pathSeparator + planner;
	}

	/** TriadMain on the class path the launcher gives {@code solve} answers as TriadCli on the whole one. */
	private Run answersAsTriadCli(String... args) throws IOException, InterruptedException {
		Run main = java(cliAndPlanner(), TriadMain.class.getName(), args);
		assertEquals(java(CLASS_PATH, TriadCli.class.getName(), args), main, String.join(" ", args));
		return main;
	}

	@Test
	void aPlanAndItsFileAreTheSame() throws IOException, InterruptedException {
		Path plan = dir.resolve("plan.txt");
		Run run = java(cliAndPlanner(), TriadMain.class.getName(), "solve", DOMAIN, PROBLEM, "-o", plan.toString(), "--timeout", "20");
		assertEquals(0, run.exit(), run.err());
		// as many actions as the cost line says (the engine's plan for gripper prob01 is 11 to 15 steps long)
		long actions = run.out().lines().filter(l -> l.startsWith("(")).count();
		assertTrue(actions >= 11 && run.out().endsWith("; cost = " + actions + " (unit cost)\n"), run.out());
		assertEquals(run.out(), Files.readString(plan));
		answersAsTriadCli("solve", DOMAIN, PROBLEM, "--planner", "triad");
	}

	@Test
	void aMissingFileAndAParseErrorAreTheSameOneLineErrors() throws IOException, InterruptedException {
		assertEquals(2, answersAsTriadCli("solve", dir.resolve("missing.pddl").toString(), PROBLEM).exit());
		Path bad = dir.resolve("bad.pddl");
		Files.writeString(bad, "(define (domain d)\n  (:predicates (p))\n  (:action a :parameters () :effect (q)))\n");
		assertTrue(answersAsTriadCli("solve", bad.toString(), PROBLEM).err().startsWith("error: " + bad + ":3:3: "));
	}

	@Test
	void anUnsolvableProblemExitsOneAlike() throws IOException, InterruptedException {
		Path problem = dir.resolve("no-balls.pddl");
		Files.writeString(problem, "(define (problem p) (:domain gripper-strips) (:objects rooma roomb ball1 left)"
				+ " (:init (room rooma) (room roomb) (ball ball1) (gripper left) (at-robby rooma) (free left))"
				+ " (:goal (at ball1 roomb)))");
		Run run = answersAsTriadCli("solve", DOMAIN, problem.toString());
		assertEquals(1, run.exit(), run.err());
	}

	/** What picocli reads (help, usage errors, option forms) goes to it, also from the planner-only class path. */
	@Test
	void helpAndUsageErrorsAreTheSame() throws IOException, InterruptedException {
		answersAsTriadCli("solve", "--help");
		answersAsTriadCli("solve", DOMAIN);
		answersAsTriadCli("solve", DOMAIN, PROBLEM, "--timeout", "soon");
		answersAsTriadCli("solve", DOMAIN, PROBLEM, "--seed", "soon");
		answersAsTriadCli("solve", DOMAIN, PROBLEM, "--planner", "metric-ff");
		answersAsTriadCli("solve", DOMAIN, PROBLEM, "--plan=" + dir.resolve("p.txt"));
		Run unknown = java(cliAndPlanner(), TriadMain.class.getName(), "solve", DOMAIN, PROBLEM, "--fast");
		assertEquals(2, unknown.exit());
		assertTrue(unknown.err().contains("Unknown option: '--fast'"), unknown.err());
	}

	@Test
	void otherCommandsGoToTriadCli() throws IOException, InterruptedException {
		Run help = java(CLASS_PATH, TriadMain.class.getName(), "--help");
		assertEquals(0, help.exit(), help.err());
		assertTrue(help.out().startsWith("Usage: triad"), help.out());
		assertEquals(java(CLASS_PATH, TriadCli.class.getName(), "check", "nowhere"), java(CLASS_PATH, TriadMain.class.getName(), "check", "nowhere"));
	}

	/** A seed read without picocli answers as picocli's command does: the plan, and the note that the seed changes nothing. */
	@Test
	void aSeedIsTheSameNote() throws IOException, InterruptedException {
		Run run = answersAsTriadCli("solve", DOMAIN, PROBLEM, "--seed", "3", "--timeout", "20");
		assertEquals(0, run.exit(), run.err());
		assertTrue(run.err().startsWith("note: seed 3 changes nothing"), run.err());
	}

	@Test
	void plainArgumentsAreReadAndTheRestLeftToPicocli() {
		SolveArguments a = SolveArguments.parse(new String[] { "solve", "d.pddl", "--timeout", "2.5", "p.pddl", "--plan", "out.txt" });
		assertEquals(Path.of("d.pddl"), a.domain);
		assertEquals(Path.of("p.pddl"), a.problem);
		assertEquals(Path.of("out.txt"), a.plan);
		assertEquals(2.5, a.timeoutSeconds);
		assertEquals("triad", a.planner);
		assertEquals(null, a.seed);
		assertEquals(5L, SolveArguments.parse(new String[] { "solve", "d.pddl", "p.pddl", "--seed", "5" }).seed);
		for (String line : List.of("solve d.pddl", "solve d.pddl p.pddl x", "solve -h", "solve d.pddl p.pddl -o", "solve d.pddl p.pddl -o a -o b",
				"solve @args", "solve d.pddl p.pddl --timeout 0", "solve d.pddl p.pddl --timeout NaN", "solve d.pddl p.pddl --timeout Infinity",
				"solve -- d.pddl p.pddl", "solve d.pddl p.pddl -oplan.txt", "solve d.pddl p.pddl --plan -x",
				"solve d.pddl p.pddl --seed 1.5", "solve d.pddl p.pddl --seed 1 --seed 2")) {
			assertEquals(null, SolveArguments.parse(line.split(" ")), line);
		}
	}
}
