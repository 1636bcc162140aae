package org.triad.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** Dry runs of the hospital's tasks through RefArc, as a user runs them with {@code triad run}. */
class RunCommandTest {
	private static final String HOSPITAL = "../models/hospital/src/main/models";

	private record Result(int code, List<String> lines, String err) {
		long count(String prefix) {
			return lines.stream().filter(l -> l.startsWith(prefix)).count();
		}
	}

	private static Result triad(String... args) {
		StringWriter out = new StringWriter();
		StringWriter err = new StringWriter();
		int code = TriadCli.execute(args, new PrintWriter(out, true), new PrintWriter(err, true));
		return new Result(code, Arrays.asList(out.toString().split("\\R")), err.toString());
	}

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { "Morning.state;GoTo(ward3)", "Morning.state;Patrol(ward1, ward2, xray)",
			"Morning.state;Fetch(gauze, storage, ward3)", "Morning.state;Deliver(syringe, ward2)",
			"Morning.state;CollectAndDeliver(gauze, storage, ward1)", "Morning.state;Guide(alice, xray)", "Morning.state;Follow(bob, lobby)",
			"Evening.state;CollectAndDeliver(bandage, ward2, lobby)", "Evening.state;Guide(alice, ward3)", "Evening.state;Follow(bob, storage)" })
	void everyHospitalTaskCompletes(String state, String task) {
		Result r = triad("run", HOSPITAL, "--state", state, "--task", task);
		assertEquals(0, r.code(), String.join("\n", r.lines()) + r.err());
		assertEquals("task " + task + " completed", r.lines().get(r.lines().size() - 1));
		assertEquals(0, r.count("replanning"));
	}

	@Test
	void injectedFailureIsReplannedAndTheTaskCompletes() {
		Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--fail", "move@2");
		assertEquals(0, r.code(), String.join("\n", r.lines()));
		assertEquals(1, r.count("replanning IsAt(ward3) (1 of 3): action Courier.move(c4, c5) failed"));
		assertEquals(2, r.count("plan for IsAt(ward3)"));
	}

	@Test
	void impossibleGoalAbortsAtOnceWithRemoteOperation() {
		// the courier's moves drain its battery, so its first goal is planned with the rest of the task in view (a task
		// does not strand its robot): the missing gauze is found before the courier drives to the storage. The planner
		// proved it (the task unsolvable from here) and nothing has moved since, so RefArc does not ask again
		Result r = triad("run", HOSPITAL, "--state", "Shortage.state", "--task", "CollectAndDeliver(gauze, storage, ward1)");
		assertEquals(1, r.code(), String.join("\n", r.lines()));
		assertEquals(0, r.count("replanning"), r.lines().toString());
		assertEquals(0, r.count("Courier.move"), "the courier did not move: " + r.lines());
		assertEquals(1, r.count("task CollectAndDeliver(gauze, storage, ward1) aborted at goal IsAt(storage): planning failed:"
				+ " Holds(gauze) unreachable after IsAt(storage) (no plan: Holds(gauze) unreachable: Courier.carries(gauze) needs"
				+ " Building.itemAt(gauze, _): none in the current state, and no action makes one from what can be reached)"), r.lines().toString());
		assertTrue(r.lines().get(r.lines().size() - 1).startsWith("remote operation requested for task CollectAndDeliver"), r.lines().toString());
	}

	@Test
	void plannerIsChosenByConfiguration() {
		// PDDL4J has no numeric fluents, so the hospital (its moves drain the battery) is no task for it: the logistics example is
		Result pddl4j = triad("run", "../models/logistics/src/main/models", "--state", "Floor.state", "--task", "GoTo(office, library)",
				"--planner", "pddl4j");
		assertEquals(0, pddl4j.code(), String.join("\n", pddl4j.lines()) + pddl4j.err());
		Result unknown = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "Guide(alice, xray)", "--planner", "nope");
		assertEquals(2, unknown.code());
		assertTrue(unknown.err().contains("unknown planner 'nope'"), unknown.err());
	}

	@Test
	void badInputIsOneLineNotAStackTrace() {
		Result unknownObject = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(kitchen)");
		assertEquals(2, unknownObject.code());
		assertTrue(unknownObject.err().startsWith("triad run: unknown object 'kitchen'"), unknownObject.err());
		assertEquals(1, unknownObject.err().strip().lines().count());
		Result unknownAction = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(ward3)", "--fail", "fly");
		assertEquals(2, unknownAction.code());
		assertTrue(unknownAction.err().contains("no action 'fly'"), unknownAction.err());
	}

	@Test
	void anArgumentOfTheWrongTypeIsRefusedAtOnceNamingTheParameterAndBothTypes() {
		Result r = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "Guide(gauze, lobby)");
		assertEquals(2, r.code(), String.join("\n", r.lines()) + r.err());
		assertEquals("triad run: task Guide: parameter 'p' is a Person, but 'gauze' is an Item", r.err().strip());
		assertEquals(0, r.count("plan"), "nothing was planned");
		Result literal = triad("run", HOSPITAL, "--state", "Morning.state", "--task", "GoTo(3)");
		assertEquals(2, literal.code());
		assertEquals("triad run: task GoTo: parameter 'dst' is a Room, but '3' is an int", literal.err().strip());
	}
}
