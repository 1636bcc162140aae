package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.pddl4j.Pddl4jPlanner;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.PlanChecker;

/**
 * The planner stays pluggable: PDDL4J 3.8.3 plans an application's PDDL as the Planner translates it at runtime
 * (the logistics example's; a problem whose only numbers are action costs is planned without them, for the
 * fewest steps), and its plans pass the model-level plan checker. PDDL4J has no numeric fluents: the hospital,
 * whose moves drain the courier's battery, is refused with a reason naming the battery, never planned wrong.
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
	@CsvSource({ "IsAt,ward3,", "Delivered,gauze,ward1", "FollowedTo,bob,ward3" })
	void pddl4jRefusesTheHospitalsBatteryNamingIt(String goal, String a, String b) {
		List<Object> args = new ArrayList<>();
		args.add(morning.object(a).orElseThrow());
		if (b != null) {
			args.add(morning.object(b).orElseThrow());
		}
		GoalSolver pddl4j = new GoalSolver(hospital, new Pddl4jPlanner(), Duration.ofSeconds(30));
		GoalSolver.Outcome outcome = pddl4j.plan(goal, args, morning);
		assertNull(outcome.plan());
		assertTrue(outcome.failure().startsWith("planner error: PDDL4J 3.8.3 has no numeric fluents, and this task computes with ")
				&& outcome.failure().contains("(courier-battery)"), outcome.failure());
	}

	@ParameterizedTest
	@CsvSource({ "library", "lab" })
	void pddl4jPlansTheLogisticsExampleAndItsPlansCheck(String room) {
		LoadedApplication loaded = ApplicationAssembler.load(Path.of("..", "models", "logistics", "src", "main", "models"));
		assertFalse(loaded.hasErrors(), () -> loaded.diagnostics().toString());
		AppSchema schema = SchemaBuilder.build(loaded.application());
		State floor = SituationReader.read(loaded.application().getSituations().get(0), schema);
		List<Object> args = List.of(floor.object(room).orElseThrow());
		GoalSolver.Outcome outcome = new GoalSolver(schema, new Pddl4jPlanner(), Duration.ofSeconds(30)).plan("IsAt", args, floor);
		assertNull(outcome.failure());
		PlanChecker.Verdict verdict = new PlanChecker(schema).check(floor, outcome.plan(), new ModelGoal(schema, "IsAt", args));
		assertTrue(verdict.valid(), verdict.reason());
	}
}
