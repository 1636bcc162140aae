package org.triad.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.Situation;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.State;
import org.triad.planner.pddl.PddlParser;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.PlanChecker;

/**
 * The example applications' goals, planned from their situations through the PDDL translation
 * and the engine, give plans the model-level plan checker accepts.
 */
class PlanningRoundTripTest {
	private static AppSchema hospital;
	private static State morning;

	@BeforeAll
	static void load() {
		LoadedApplication app = ApplicationAssembler.load(Path.of("..", "models", "hospital", "src", "main", "models"));
		assertFalse(app.hasErrors(), () -> app.diagnostics().toString());
		hospital = SchemaBuilder.build(app.application());
		Situation s = app.application().getSituations().stream().filter(x -> x.getName().equals("Morning")).findFirst().orElseThrow();
		morning = SituationReader.read(s, hospital);
	}

	@ParameterizedTest
	@CsvSource({ "IsAt,ward3,,3", "Holds,gauze,,4", "Delivered,gauze,ward1,9", "PersonAt,alice,xray,4", "FollowedTo,bob,ward3,8",
			"PersonAt,bob,lobby,9" })
	void hospitalGoalIsPlannedOptimallyAndChecked(String goal, String a, String b, int expectedLength) {
		List<Object> args = new ArrayList<>();
		args.add(morning.object(a).orElseThrow());
		if (b != null) {
			args.add(morning.object(b).orElseThrow());
		}
		GoalSolver.Outcome outcome = new GoalSolver(hospital).plan(goal, args, morning);
		assertNull(outcome.failure());
		PlanChecker.Verdict verdict = new PlanChecker(hospital).check(morning, outcome.plan(), new ModelGoal(hospital, goal, args));
		assertTrue(verdict.valid(), verdict.reason() + " in " + outcome.plan());
		assertEquals(expectedLength, outcome.plan().size(), outcome.plan().toString());
	}

	/** Alice does not walk her own way (no Building.walksAhead(alice)): she is guided, never followed, so a goal to follow her is refused. */
	@Test
	void aPersonWhoDoesNotWalkAheadIsNotFollowed() {
		GoalSolver.Outcome outcome = new GoalSolver(hospital).plan("FollowedTo", List.of(morning.object("alice").get(), morning.object("ward2").get()), morning);
		assertFalse(outcome.planned());
		assertEquals("no plan: FollowedTo(alice, ward2) unreachable: Courier.following(alice): the actions that could reach it need"
				+ " Building.walksAhead(alice), which the current state lacks", outcome.failure());
	}

	@Test
	void unreachableGoalYieldsNoPlanNotAnException() {
		State isolated = morning.toBuilder().retract(Atom.of("Building", "adj", morning.object("lobby").get(), morning.object("c4").get()))
				.retract(Atom.of("Building", "adj", morning.object("c4").get(), morning.object("lobby").get())).build();
		GoalSolver.Outcome outcome = new GoalSolver(hospital).plan("IsAt", List.of(morning.object("ward3").get()), isolated);
		assertFalse(outcome.planned());
		assertTrue(outcome.failure().startsWith("no plan"), outcome.failure());
	}

	/** The planner gets the typed model directly; its text (triad pddl, external planners) must mean exactly the same. */
	@ParameterizedTest
	@CsvSource({ "IsAt,ward3,", "Holds,gauze,", "Delivered,gauze,ward1", "PersonAt,alice,xray", "FollowedTo,bob,ward3" })
	void typedTranslationIsWhatItsTextParsesBackTo(String goal, String a, String b) {
		List<Object> args = new ArrayList<>();
		args.add(morning.object(a).orElseThrow());
		if (b != null) {
			args.add(morning.object(b).orElseThrow());
		}
		var task = new GoalSolver(hospital).translator().translate(morning, hospital.goal(goal).orElseThrow(),
				new ModelGoal(hospital, goal, args).binding());
		assertEquals(task.domain(), PddlParser.parseDomain(task.domainText(), "domain.pddl"), task.domainText());
		assertEquals(task.problem(), PddlParser.parseProblem(task.problemText(), "problem.pddl"), task.problemText());
		assertEquals(9, task.domain().actions().size(), task.domainText()); // the courier's 6 (recharge among them), the building's walk, passDoor, ride
	}
}
