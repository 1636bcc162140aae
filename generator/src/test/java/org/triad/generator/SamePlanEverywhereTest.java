package org.triad.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.Situation;
import org.triad.planner.PddlStep;
import org.triad.planner.SolveResult;
import org.triad.planner.TriadEngine;
import org.triad.planner.pddl.PddlParser;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.ModelGoal;
import org.triad.runtime.schema.PddlTranslator;

/**
 * A goal gets the same plan from RefArc's path (GoalSolver, the typed model, a planner shared by the
 * goals of a run) as from {@code ./triad solve} on the text {@code ./triad pddl} writes (parsed
 * back, a fresh engine), and the same again under a parallel CPU load. No timing is asserted.
 */
class SamePlanEverywhereTest {
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
	@CsvSource({ "IsAt,ward3,", "Holds,gauze,", "Delivered,gauze,ward1", "PersonAt,alice,xray", "FollowedTo,bob,ward3", "PersonAt,bob,lobby" })
	void goalSolverAndSolveOnTheWrittenTextGiveOnePlanLoadedOrNot(String goal, String a, String b) throws InterruptedException {
		List<Object> args = new ArrayList<>();
		args.add(morning.object(a).orElseThrow());
		if (b != null) {
			args.add(morning.object(b).orElseThrow());
		}
		GoalSolver solver = new GoalSolver(hospital);
		String perGoal = planOf(solver, goal, args);
		PddlTranslator.Task task = solver.translator().translate(morning, hospital.goal(goal).orElseThrow(), new ModelGoal(hospital, goal, args).binding());
		SolveResult r = new TriadEngine().solve(PddlParser.parseDomain(task.domainText(), "domain.pddl"),
				PddlParser.parseProblem(task.problemText(), "problem.pddl"), Duration.ofMinutes(2));
		assertTrue(r.isSolved(), r.message());
		List<PddlStep> steps = r.plan().steps();
		String solved = task.plan(steps.stream().map(PddlStep::name).toList(), steps.stream().map(PddlStep::args).toList()).toString();
		assertEquals(perGoal, solved, "triad solve on the written PDDL");

		AtomicBoolean stop = new AtomicBoolean();
		List<Thread> load = new ArrayList<>();
		for (int i = 0; i < 2 * Runtime.getRuntime().availableProcessors(); i++) {
			Thread t = new Thread(() -> {
				long x = 1;
				while (!stop.get()) {
					x = x * 6364136223846793005L + 1;
				}
				if (x == 42) {
					System.out.print("");
				}
			});
			t.setDaemon(true);
			t.start();
			load.add(t);
		}
		try {
			for (int i = 0; i < 5; i++) {
				assertEquals(perGoal, planOf(solver, goal, args), "run " + i + " under load");
			}
		} finally {
			stop.set(true);
			for (Thread t : load) {
				t.join();
			}
		}
	}

	private static String planOf(GoalSolver solver, String goal, List<Object> args) {
		GoalSolver.Outcome outcome = solver.plan(goal, args, morning);
		assertNull(outcome.failure());
		return outcome.plan().toString();
	}
}
