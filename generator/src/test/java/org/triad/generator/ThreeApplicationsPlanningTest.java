package org.triad.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.PlanChecker;

/**
 * Three differently shaped applications (logistics: the paper's listings; hospital: a world action,
 * functions and relations; lab: a ternary relation, abstract types, inheritance in parameters, an
 * enumeration-valued property and a world action the plan needs): their goals, planned from their
 * situations, give plans the plan checker accepts, and unreachable goals give "no plan".
 */
class ThreeApplicationsPlanningTest {

	private static String folder(String app) {
		return switch (app) {
			case "lab" -> "src/test/resources/apps/lab";
			default -> "../models/" + app + "/src/main/models";
		};
	}

	// The hospital's delivery is planned shortest in metres, and every metre drains the battery: Evening's courier
	// (25 %, 0.5 % a metre) cannot drive the 58 m of the direct delivery, so it charges at the lobby's dock on the way
	// (15 steps, HospitalBatteryPlanningTest says more).
	@ParameterizedTest(name = "{0}: {2}({3}) from {1}")
	@CsvSource(delimiter = ';', value = { "logistics;Floor;IsAt;library;4", "logistics;Floor;IsAt;lab;3",
			"hospital;Evening;Delivered;gauze ward1;15", "hospital;Evening;FollowedTo;bob ward2;4",
			"lab;Bench;Reached;analyser;3", "lab;Bench;Analysed;s1 analyser;7", "lab;Bench;Reached;store;1" })
	void goalIsPlannedAndThePlanChecks(String app, String situation, String goal, String args, int length) {
		AppSchemaAndState s = load(app, situation);
		List<Object> values = objects(s.state(), args);
		GoalSolver.Outcome outcome = new GoalSolver(s.schema()).plan(goal, values, s.state());
		assertNull(outcome.failure());
		PlanChecker.Verdict verdict = new PlanChecker(s.schema()).check(s.state(), outcome.plan(), new ModelGoal(s.schema(), goal, values));
		assertTrue(verdict.valid(), verdict.reason() + " " + outcome.plan());
		assertEquals(length, outcome.plan().size(), outcome.plan().toString());
	}

	@ParameterizedTest(name = "{0}: {2}({3}) unreachable")
	@CsvSource(delimiter = ';', value = {
			"logistics;Floor;IsAt;c1;IsAt(c1) unreachable: LogisticsRobot.loc() == c1: the actions that could reach it need"
					+ " RoomsWorld.adj(office, c1), which the current state lacks",
			"hospital;Shortage;Holds;gauze;Holds(gauze) unreachable: Courier.carries(gauze) needs Building.itemAt(gauze, _):"
					+ " none in the current state, and no action makes one from what can be reached",
			"hospital;Morning;IsAt;ward1;IsAt(ward1) unreachable: Courier.loc() == ward1: the actions that could reach it need"
					+ " Building.adj(_, ward1) or Building.doorway(pharmacyDoor, _, ward1) or Building.landing(lift, ward1)"
					+ " (for any reachable _), which the current state lacks",
			"lab;Bench;Reached;vault;Reached(vault) unreachable: Rover.at() == vault: the actions that could reach it need"
					+ " LabWorld.linked(_, _, vault) (for any reachable _), which the current state lacks" })
	void unreachableGoalGivesNoPlanAndSaysWhy(String app, String situation, String goal, String args, String why) {
		AppSchemaAndState s = load(app, situation);
		State state = s.state();
		if (app.equals("logistics")) {
			// cut the office off: nothing links it any more
			State.Builder b = state.toBuilder();
			Object office = state.object("office").orElseThrow();
			state.values().keySet().stream().filter(a -> a.property().equals("adj") && a.args().contains(office)).forEach(b::retract);
			state = b.build();
		}
		if (app.equals("hospital") && situation.equals("Morning")) {
			// injected faults: the fire door c2-c3 is closed and people block the corridor c3-c6
			State.Builder b = state.toBuilder();
			Object c3 = state.object("c3").orElseThrow();
			Object ward1 = state.object("ward1").orElseThrow();
			state.values().keySet().stream().filter(a -> a.property().equals("adj") && a.args().contains(c3) && !a.args().contains(ward1))
					.forEach(b::retract);
			state = b.build();
		}
		GoalSolver.Outcome outcome = new GoalSolver(s.schema()).plan(goal, objects(state, args), state);
		assertFalse(outcome.planned());
		assertEquals("no plan: " + why, outcome.failure());
	}

	private record AppSchemaAndState(AppSchema schema, State state) {
	}

	private static AppSchemaAndState load(String app, String situation) {
		LoadedApplication loaded = ApplicationAssembler.load(Path.of(folder(app)));
		assertFalse(loaded.hasErrors(), () -> loaded.diagnostics().toString());
		AppSchema schema = SchemaBuilder.build(loaded.application());
		State state = SituationReader.read(loaded.application().getSituations().stream().filter(x -> x.getName().equals(situation))
				.findFirst().orElseThrow(), schema);
		return new AppSchemaAndState(schema, state);
	}

	private static List<Object> objects(State state, String names) {
		List<Object> values = new ArrayList<>();
		for (String n : names.split(" ")) {
			values.add(state.object(n).orElseThrow(() -> new AssertionError("no object " + n)));
		}
		return values;
	}
}
