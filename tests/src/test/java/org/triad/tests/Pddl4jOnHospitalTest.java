package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.pddl4j.Pddl4jPlanner;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.PlanChecker;

/**
 * The hospital application's PDDL, as the Planner translates it at runtime, is accepted by
 * PDDL4J 3.8.3 (the planner stays pluggable), and PDDL4J's plans pass the model-level plan checker.
 * PDDL4J has no numeric fluents; the hospital's only numbers are its moves' costs (their length), which
 * the plug-in leaves out (it plans fewest moves, not fewest metres).
 */
class Pddl4jOnHospitalTest {
	private static AppSchema hospital;
	private static State morning;

	@BeforeAll
	static void load() {
		HospitalModels models = HospitalModels.load();
		hospital = models.schema;
		morning = models.situation("Morning");
	}

	@ParameterizedTest
	@CsvSource({ "IsAt,ward3,", "Holds,gauze,", "Delivered,gauze,ward1", "PersonAt,alice,xray", "FollowedTo,alice,ward2" })
	void pddl4jParsesPlansAndItsPlansCheck(String goal, String a, String b) {
		List<Object> args = new ArrayList<>();
		args.add(morning.object(a).orElseThrow());
		if (b != null) {
			args.add(morning.object(b).orElseThrow());
		}
		GoalSolver pddl4j = new GoalSolver(hospital, new Pddl4jPlanner(), Duration.ofSeconds(30));
		GoalSolver.Outcome outcome = pddl4j.plan(goal, args, morning);
		assertNull(outcome.failure());
		PlanChecker.Verdict verdict = new PlanChecker(hospital).check(morning, outcome.plan(), new ModelGoal(hospital, goal, args));
		assertTrue(verdict.valid(), verdict.reason());
	}
}
