package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.cli.TriadCliTest.Run;

/** {@code triad solve} as a user meets it: plans, plan files, exit codes and one-line errors. */
class SolveCommandTest {
	private static final Path HOSPITAL = Path.of("..", "planner", "src", "test", "resources", "pddl", "hospital");
	private static final String DOMAIN = HOSPITAL.resolve("domain.pddl").toString();
	private static final String PROBLEM = HOSPITAL.resolve("p-10-a.pddl").toString();

	@TempDir
	Path dir;

	@Test
	void printsAPlanVALReadsAndWritesThePlanFile() throws IOException {
		Path plan = dir.resolve("plan.txt");
		Run run = TriadCliTest.run("solve", DOMAIN, PROBLEM, "-o", plan.toString(), "--timeout", "20");
		assertEquals(0, run.exit(), run.err());
		List<String> lines = run.out().lines().toList();
		assertEquals("; cost = 3 (unit cost)", lines.get(lines.size() - 1));
		assertTrue(lines.get(0).matches("\\(move wp0 \\S+\\)"), lines.get(0));
		assertEquals(run.out(), Files.readString(plan));
	}

	/** A problem with a {@code :metric} is planned for it, and the cost line states the metric's value, not the steps. */
	@Test
	void theCostLineOfAProblemWithAMetricIsTheMetricsValue() {
		Path roads = Path.of("..", "planner", "src", "test", "resources", "pddl", "metric");
		Run run = TriadCliTest.run("solve", roads.resolve("roads-domain.pddl").toString(), roads.resolve("roads-route.pddl").toString(),
				"--timeout", "20");
		assertEquals(0, run.exit(), run.err());
		List<String> lines = run.out().lines().toList();
		// the corridor: three roads of 10 m, not the direct road of 50 m
		assertEquals(List.of("(move lobby c1)", "(move c1 c2)", "(move c2 ward)"), lines.subList(0, lines.size() - 1));
		assertEquals("; cost = 30 (metric)", lines.get(lines.size() - 1));
	}

	@Test
	void helpNamesEveryOption() {
		Run run = TriadCliTest.run("solve", "--help");
		assertEquals(0, run.exit(), run.err());
		for (String option : List.of("DOMAIN", "PROBLEM", "--plan", "--planner", "--timeout", "--seed")) {
			assertTrue(run.out().contains(option), option + " in " + run.out());
		}
		assertTrue(run.out().replaceAll("\\s+", " ").contains("changes nothing: no part of planning is randomized"), run.out());
	}

	/** Nothing in planning is randomized: a seed is accepted, gives the plan every seed gives, and the note beside it says so. */
	@Test
	void aSeedIsAcceptedAndSaidToChangeNothing() {
		Run none = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--timeout", "20");
		Run seven = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--timeout", "20", "--seed", "7");
		Run other = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--seed=123456789", "--timeout", "20");
		assertEquals(0, seven.exit(), seven.err());
		assertEquals(none.out(), seven.out());
		assertEquals(none.out(), other.out());
		assertEquals("", none.err());
		assertEquals("note: " + SolveRun.SEED_NOTE.replace("SEED", "7"), seven.err().strip());
		assertTrue(other.err().startsWith("note: seed 123456789 changes nothing"), other.err());
		Run bad = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--seed", "x");
		assertEquals(2, bad.exit(), bad.err());
		assertTrue(bad.err().contains("--seed"), bad.err());
	}

	@Test
	void exitsOneWithoutAPlan() throws IOException {
		Path problem = dir.resolve("island.pddl");
		Files.writeString(problem, "(define (problem island) (:domain hospital) (:objects a b - waypoint)"
				+ " (:init (robot-at a) (hand-empty)) (:goal (robot-at b)))");
		Run run = TriadCliTest.run("solve", DOMAIN, problem.toString());
		assertEquals(1, run.exit(), run.err());
		assertTrue(run.err().startsWith("no plan: problem is unsolvable"), run.err());
	}

	@Test
	void aTaskTooLargeIsRefusedInOneLineAndTheTimeoutHoldsWhileGrounding() throws IOException {
		Path domain = dir.resolve("free3.pddl");
		Files.writeString(domain, "(define (domain free3) (:requirements :strips :typing) (:types obj) (:predicates (done ?a ?b ?c - obj))"
				+ " (:action act :parameters (?a ?b ?c - obj) :precondition (and) :effect (done ?a ?b ?c)))");
		Run huge = TriadCliTest.run("solve", domain.toString(), free3(1000).toString(), "--timeout", "10");
		assertEquals(2, huge.exit(), huge.err());
		assertTrue(huge.err().startsWith("error: grounding would create 1·10⁹ actions of 'act' (3 parameters no precondition binds, 1,000 objects each)"),
				huge.err());
		assertEquals(1, huge.err().strip().lines().count(), huge.err());
		// 10⁶ actions fit the estimate but take longer than half a second to ground
		Run slow = TriadCliTest.run("solve", domain.toString(), free3(100).toString(), "--timeout", "0.5");
		assertEquals(1, slow.exit(), slow.err());
		assertTrue(slow.err().matches("no plan: time limit of 0.5 s reached while (parsing|grounding)\\R?"), slow.err());
	}

	private Path free3(int objects) throws IOException {
		StringBuilder names = new StringBuilder();
		for (int i = 0; i < objects; i++) {
			names.append(" o").append(i);
		}
		Path problem = dir.resolve("free3-" + objects + ".pddl");
		Files.writeString(problem, "(define (problem f) (:domain free3) (:objects" + names + " - obj) (:init) (:goal (done o1 o2 o3)))");
		return problem;
	}

	@Test
	void exitsTwoWithOneLineOnUsageAndInputErrors() throws IOException {
		Run one = TriadCliTest.run("solve", "only-one.pddl");
		assertEquals(2, one.exit());
		assertTrue(one.err().contains("Missing required parameter: 'PROBLEM'"), one.err());

		Run unknown = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--planner", "metric-ff");
		assertEquals(2, unknown.exit());
		assertTrue(unknown.err().contains("unknown planner 'metric-ff'"), unknown.err());

		Run missing = TriadCliTest.run("solve", dir.resolve("missing.pddl").toString(), PROBLEM);
		assertEquals(2, missing.exit());
		assertTrue(missing.err().startsWith("error: no such file: "), missing.err());

		Path bad = dir.resolve("bad.pddl");
		Files.writeString(bad, "(define (domain d)\n  (:predicates (p))\n  (:action a :parameters () :effect (q)))\n");
		Run undeclared = TriadCliTest.run("solve", bad.toString(), PROBLEM);
		assertEquals(2, undeclared.exit());
		assertTrue(undeclared.err().startsWith("error: " + bad + ":3:3: action 'a' uses undeclared predicate 'q'"), undeclared.err());

		Run soon = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--timeout", "soon");
		assertEquals(2, soon.exit());
		assertTrue(soon.err().contains("'soon' is not a double"), soon.err());

		Run negative = TriadCliTest.run("solve", DOMAIN, PROBLEM, "--timeout", "-1");
		assertEquals(2, negative.exit());
		assertTrue(negative.err().contains("--timeout must be a positive number of seconds"), negative.err());
	}

	@Test
	void aNumericFluentLeftUndefinedIsALocatedErrorWhereTheGoalNeedsItAndPddlsUndefinedValueElsewhere() throws IOException {
		Path numeric = Path.of("..", "planner", "src", "test", "resources", "pddl", "numeric");
		String domain = numeric.resolve("battery-domain.pddl").toString();
		String far = Files.readString(numeric.resolve("battery-problem.pddl"));
		Path noCapacity = dir.resolve("no-capacity.pddl");
		Files.writeString(noCapacity, far.replace("(= (capacity r1) 100)", "").replace("(:goal (and", "(:goal (and (> (capacity r1) 0)"));
		Run goal = TriadCliTest.run("solve", domain, noCapacity.toString());
		assertEquals(2, goal.exit(), goal.err());
		assertEquals("error: " + noCapacity + ":9:18: the goal reads (capacity r1), which :init gives no value and no action assigns,"
				+ " so it could never hold; give it one with (= (capacity r1) NUMBER)", goal.err().strip());

		// one road without a length: its instances of drive do not apply (PDDL 2.1), and the answer says so
		Path noRoad = dir.resolve("no-road.pddl");
		Files.writeString(noRoad, far.replace("(= (distance c2 ward) 20)", ""));
		Run road = TriadCliTest.run("solve", domain, noRoad.toString());
		assertEquals(1, road.exit(), road.err());
		assertTrue(road.err().contains("(distance c2 ward) has no value in :init (and no action assigns it), so 1 instance of 'drive' that read it never apply"),
				road.err());
	}

	@Test
	void anUnwritablePlanFileIsAnErrorWithItsCause() throws IOException {
		Path notAFolder = dir.resolve("file");
		Files.writeString(notAFolder, "x");
		Run run = TriadCliTest.run("solve", DOMAIN, PROBLEM, "-o", notAFolder.resolve("plan.txt").toString());
		assertEquals(2, run.exit());
		assertTrue(run.err().startsWith("error: cannot write the plan file "), run.err());
	}
}
