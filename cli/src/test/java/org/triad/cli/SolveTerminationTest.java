package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedWriter;
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
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * SIGTERM ends {@code triad solve} (the launcher's entry, a real process) in every phase of planning:
 * it exits with 143 (128 + SIGTERM) and leaves no process behind; and {@code --timeout} holds while
 * parsing. Each input keeps the process in its phase for seconds of CPU, and the signal is sent only
 * once a thread dump ({@code jcmd PID Thread.print}) shows the phase's class on a stack, so the signal
 * arrives in that phase whatever the machine's load. No time is asserted beyond generous bounds.
 * A {@code --timeout} that ends improvement gives the plan found so far, said so, with exit 0.
 */
class SolveTerminationTest {
	private static final String CLASS_PATH = System.getProperty("java.class.path");
	private static final String FREE2 = "(define (domain free2) (:requirements :strips :typing) (:types obj)"
			+ " (:predicates (done ?a ?b - obj))"
			+ " (:action act :parameters (?a ?b - obj) :precondition (and) :effect (done ?a ?b)))";
	private static final String GRIPPER = "(define (domain gripper) (:requirements :strips)"
			+ " (:predicates (room ?r) (ball ?b) (gripper ?g) (at-robby ?r) (at ?b ?r) (free ?g) (carry ?o ?g))"
			+ " (:action move :parameters (?from ?to) :precondition (and (room ?from) (room ?to) (at-robby ?from))"
			+ " :effect (and (at-robby ?to) (not (at-robby ?from))))"
			+ " (:action pick :parameters (?obj ?room ?gripper)"
			+ " :precondition (and (ball ?obj) (room ?room) (gripper ?gripper) (at ?obj ?room) (at-robby ?room) (free ?gripper))"
			+ " :effect (and (carry ?obj ?gripper) (not (at ?obj ?room)) (not (free ?gripper))))"
			+ " (:action drop :parameters (?obj ?room ?gripper)"
			+ " :precondition (and (ball ?obj) (room ?room) (gripper ?gripper) (carry ?obj ?gripper) (at-robby ?room))"
			+ " :effect (and (at ?obj ?room) (free ?gripper) (not (carry ?obj ?gripper)))))";

	@TempDir
	Path dir;

	/** A phase, the input that keeps {@code solve} in it for seconds, and the class on a stack while it lasts. */
	enum Phase {
		/** a 20 MB problem file (about 4 s of CPU to read) */
		PARSING("org.triad.planner.pddl.PddlParser."),
		/** an action of two free parameters over 600 objects: 360,000 ground actions */
		GROUNDING("org.triad.planner.Grounder."),
		/** 250 balls to carry: the goal agenda's plan of 1,000 steps is quick, improving it takes its whole budget */
		IMPROVEMENT("org.triad.planner.PlanImprover.");

		final String marker;

		Phase(String marker) {
			this.marker = marker;
		}
	}

	@ParameterizedTest
	@EnumSource(Phase.class)
	void sigtermEndsEveryPhaseAndLeavesNoProcess(Phase phase) throws IOException, InterruptedException {
		Path[] files = input(phase);
		Process p = solve(files[0], files[1], "600");
		try {
			awaitOnStack(p, phase.marker);
			terminatedBySigterm(p);
		} finally {
			p.destroyForcibly();
			p.waitFor();
		}
	}

	/** The search phase: more pigeons than holes (every relaxed plan exists, no plan does), a search that never ends on its own. */
	@Test
	void sigtermEndsASearchAndLeavesNoProcess() throws IOException, InterruptedException {
		Path domain = dir.resolve("holes.pddl");
		Files.writeString(domain, "(define (domain holes) (:requirements :strips) (:predicates (pigeon ?p) (hole ?h) (out ?p) (free ?h) (placed ?p))"
				+ " (:action put :parameters (?p ?h) :precondition (and (pigeon ?p) (hole ?h) (out ?p) (free ?h))"
				+ " :effect (and (placed ?p) (not (out ?p)) (not (free ?h)))))");
		StringBuilder objects = new StringBuilder();
		StringBuilder init = new StringBuilder();
		StringBuilder goal = new StringBuilder();
		int holes = 14;
		for (int i = 0; i <= holes; i++) {
			objects.append(" p").append(i);
			init.append(" (pigeon p").append(i).append(") (out p").append(i).append(")");
			goal.append(" (placed p").append(i).append(")");
			if (i < holes) {
				objects.append(" h").append(i);
				init.append(" (hole h").append(i).append(") (free h").append(i).append(")");
			}
		}
		Path problem = dir.resolve("pigeons.pddl");
		Files.writeString(problem, "(define (problem pigeons) (:domain holes) (:objects" + objects + ") (:init" + init + ") (:goal (and" + goal + ")))");
		Process p = solve(domain, problem, "600");
		try {
			awaitOnStack(p, "org.triad.planner.TriadEngine.search(");
			terminatedBySigterm(p);
		} finally {
			p.destroyForcibly();
			p.waitFor();
		}
	}

	/** The timeout holds while the files are read: one line naming the phase, exit 1, at once. */
	@Test
	void theTimeoutHoldsWhileParsing() throws IOException, InterruptedException {
		Path[] files = input(Phase.PARSING);
		Process p = solve(files[0], files[1], "0.5");
		try {
			assertTrue(p.waitFor(2, TimeUnit.MINUTES), "still running two minutes after a timeout of half a second");
			String out = Files.readString(dir.resolve("out.txt"));
			assertEquals(1, p.exitValue(), out);
			assertEquals("no plan: time limit of 0.5 s reached while parsing", out.strip());
		} finally {
			p.destroyForcibly();
			p.waitFor();
		}
	}

	/**
	 * {@code --timeout} reached while the goal agenda's plan of 250 balls is being improved: the process prints that plan
	 * (valid), says on a {@code note:} line that it is the best found so far, exits 0 as documented, and ends within a
	 * bound of its timeout. Its first plan costs about a tenth of the CPU its improvement does, so some timeout lies
	 * between the two at any load: the test starts at 4 s and doubles the timeout while the time ran out before the first
	 * plan (a slow or loaded machine), up to 128 s.
	 */
	@Test
	void theTimeoutDuringImprovementGivesTheBestPlanSoFarAndExitZero() throws Exception {
		Path[] files = input(Phase.IMPROVEMENT);
		for (int timeout = 4; timeout <= 128; timeout *= 2) {
			Process p = solve(files[0], files[1], Integer.toString(timeout));
			try {
				assertTrue(p.waitFor(timeout + 120, TimeUnit.SECONDS), "still running two minutes after its timeout of " + timeout + " s");
				String out = Files.readString(dir.resolve("out.txt"));
				if (out.startsWith("no plan: time limit of ")) {
					assertEquals(1, p.exitValue(), out);
					continue; // the time ran out before the first plan: more time
				}
				assertEquals(0, p.exitValue(), out);
				List<String> lines = out.lines().toList();
				List<String> notes = lines.stream().filter(l -> l.startsWith("note: ")).toList();
				assertEquals(List.of("note: " + org.triad.planner.SolveResult.BEST_SO_FAR + " (a longer --timeout gives the same plan on every run)"),
						notes, "a plan improved to the end, or another note, with a timeout of " + timeout + " s: " + lines.size() + " lines");
				String plan = lines.stream().filter(l -> !l.startsWith("note: ")).collect(java.util.stream.Collectors.joining("\n"));
				org.triad.planner.PddlPlan parsed = org.triad.planner.ExternalPlanner.parsePlan(plan);
				assertTrue(parsed.length() >= 749, "250 balls take at least 749 steps: " + parsed.length());
				assertTrue(org.triad.planner.PlanValidator.validate(org.triad.planner.pddl.PddlParser.parseDomain(files[0]),
						org.triad.planner.pddl.PddlParser.parseProblem(files[1]), parsed).valid(), "the best plan so far is not valid");
				return;
			} finally {
				p.destroyForcibly();
				p.waitFor();
			}
		}
		fail("no first plan within 128 s");
	}

	private Path[] input(Phase phase) throws IOException {
		Path domain = dir.resolve("domain.pddl");
		Path problem = dir.resolve("problem.pddl");
		switch (phase) {
			case PARSING -> {
				Files.writeString(domain, FREE2);
				try (BufferedWriter w = Files.newBufferedWriter(problem, StandardCharsets.UTF_8)) {
					w.write("(define (problem big) (:domain free2) (:objects o0 o1 - obj) (:init\n");
					for (int i = 0; i < 400_000; i++) {
						w.write("(done o0 o1) (done o1 o0) (done o0 o0) (done o1 o1)\n");
					}
					w.write(") (:goal (done o1 o0)))\n");
				}
			}
			case GROUNDING -> {
				Files.writeString(domain, FREE2);
				StringBuilder objects = new StringBuilder();
				for (int i = 0; i < 600; i++) {
					objects.append(" o").append(i);
				}
				Files.writeString(problem, "(define (problem wide) (:domain free2) (:objects" + objects + " - obj) (:init)"
						+ " (:goal (and (done o1 o2) (done o3 o4))))");
			}
			case IMPROVEMENT -> {
				Files.writeString(domain, GRIPPER);
				StringBuilder objects = new StringBuilder();
				StringBuilder init = new StringBuilder();
				StringBuilder goal = new StringBuilder();
				for (int i = 0; i < 250; i++) {
					objects.append(" b").append(i);
					init.append(" (ball b").append(i).append(") (at b").append(i).append(" rooma)");
					goal.append(" (at b").append(i).append(" roomb)");
				}
				Files.writeString(problem, "(define (problem balls) (:domain gripper) (:objects rooma roomb left right" + objects + ")"
						+ " (:init (room rooma) (room roomb) (gripper left) (gripper right) (at-robby rooma) (free left) (free right)" + init + ")"
						+ " (:goal (and" + goal + ")))");
			}
		}
		return new Path[] { domain, problem };
	}

	private Process solve(Path domain, Path problem, String timeout) throws IOException {
		return new ProcessBuilder(java("java"), "-Xmx768m", "-cp", cliAndPlanner(),
				TriadMain.class.getName(), "solve", domain.toString(), problem.toString(), "--timeout", timeout)
				.redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
	}

	/** SIGTERM now: the process ends with 143 within two minutes, and nothing it started runs on. */
	private void terminatedBySigterm(Process p) throws IOException, InterruptedException {
		List<ProcessHandle> children = p.descendants().toList();
		p.destroy(); // SIGTERM
		assertTrue(p.waitFor(2, TimeUnit.MINUTES), "still running two minutes after SIGTERM");
		assertEquals(143, p.exitValue(), Files.readString(dir.resolve("out.txt")));
		for (ProcessHandle c : children) {
			assertFalse(c.isAlive(), "left behind: " + c.info());
		}
	}

	/**
	 * Waits until a thread dump of the process shows {@code frame} (the start of a stack frame) on a stack (at most three
	 * minutes); fails if the process ends first, or the phase is never seen.
	 */
	private void awaitOnStack(Process p, String frame) throws IOException, InterruptedException {
		long until = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
		while (System.nanoTime() < until) {
			if (!p.isAlive()) {
				fail("ended (exit " + p.exitValue() + ") before " + frame + " was seen: " + Files.readString(dir.resolve("out.txt")));
			}
			if (threadDump(p).contains(frame)) {
				return;
			}
			Thread.sleep(100);
		}
		fail(frame + " not seen on a stack within three minutes");
	}

	/** {@code jcmd PID Thread.print} of the JDK running the tests ("" while the process cannot be attached to yet). */
	private String threadDump(Process p) throws IOException, InterruptedException {
		List<String> command = new ArrayList<>(List.of(java("jcmd"), Long.toString(p.pid()), "Thread.print"));
		Process jcmd = new ProcessBuilder(command).redirectErrorStream(true).start();
		byte[] out = jcmd.getInputStream().readAllBytes();
		if (!jcmd.waitFor(1, TimeUnit.MINUTES)) {
			jcmd.destroyForcibly();
			return "";
		}
		return new String(out, StandardCharsets.UTF_8);
	}

	private static String java(String tool) {
		return Path.of(System.getProperty("java.home"), "bin", tool).toString();
	}

	/** This module's classes and the planner's, as the launcher's {@code solve} class path has them. */
	private static String cliAndPlanner() {
		String cli = Path.of("target", "classes").toAbsolutePath().toString();
		String planner = Arrays.stream(CLASS_PATH.split(File.pathSeparator))
				.filter(e -> e.contains("triad-planner-") || e.replace('\\', '/').endsWith("planner/target/classes"))
				.findFirst().orElseThrow(() -> new AssertionError("no planner on the test class path " + CLASS_PATH));
		return cli + File.pathSeparator + planner;
	}
}
