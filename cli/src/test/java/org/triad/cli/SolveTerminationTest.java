package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * SIGTERM ends {@code triad solve} (the launcher's entry, a real process) while it plans: it exits
 * with 143 (128 + SIGTERM) and leaves no process behind. The input is a search that never ends on
 * its own (more pigeons than holes: every relaxed plan exists, no plan does), so the signal arrives
 * in the search whatever the machine's load. No time is asserted beyond generous bounds.
 */
class SolveTerminationTest {
	private static final String CLASS_PATH = System.getProperty("java.class.path");

	@TempDir
	Path dir;

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

		Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx512m", "-cp", cliAndPlanner(),
				TriadMain.class.getName(), "solve", domain.toString(), problem.toString(), "--timeout", "600")
				.redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
		try {
			// past the JVM's start, parsing and grounding (tiny here): the search has the CPU
			awaitCpu(p, Duration.ofSeconds(3), Duration.ofMinutes(3));
			assertTrue(p.isAlive(), "the search ended on its own: " + Files.readString(dir.resolve("out.txt")));
			List<ProcessHandle> children = p.descendants().toList();
			p.destroy(); // SIGTERM
			assertTrue(p.waitFor(2, TimeUnit.MINUTES), "still running two minutes after SIGTERM");
			assertEquals(143, p.exitValue(), Files.readString(dir.resolve("out.txt")));
			for (ProcessHandle c : children) assertFalse(c.isAlive(), "left behind: " + c.info());
		} finally {
			p.destroyForcibly();
			p.waitFor();
		}
	}

	/** Waits until the process has used {@code cpu} of processor time (or ended, or {@code atMost} passed). */
	private static void awaitCpu(Process p, Duration cpu, Duration atMost) throws InterruptedException {
		long until = System.nanoTime() + atMost.toNanos();
		while (p.isAlive() && System.nanoTime() < until) {
			Duration used = p.info().totalCpuDuration().orElse(Duration.ZERO);
			if (used.compareTo(cpu) >= 0) return;
			Thread.sleep(100);
		}
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
