package org.triad.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.triad.examples.hospital.VerifiedHospital;
import org.triad.refarc.GoalPlanner;
import org.triad.refarc.PlanningOutcome;
import org.triad.refarc.Status;
import org.triad.refarc.model.DryRunWorld;
import org.triad.refarc.model.SchemaGoalPlanner;
import org.triad.refarc.model.SchemaPlanCheck;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.runtime.component.DeterministicScheduler;
import org.triad.runtime.component.Scheduler;
import org.triad.runtime.schema.AppSchema;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.ModelTask;

/**
 * Plan verification, which the paper names as hard to add to its architecture, is one component and
 * two connectors here: the hospital's architecture model (models/hospital/src/main/arc,
 * VerifiedHospital.arc) is generated into Java by the build; on the real hospital models, the verifier (replaying plans with the models'
 * pre- and postconditions) rejects a corrupted plan, RefArc re-plans, and a planner that always
 * corrupts ends in a remote-operation request after four refutations.
 */
class PlanVerifierExtensionTest {
	private static AppSchema hospital;
	private static State morning;

	@BeforeAll
	static void load() {
		HospitalModels models = HospitalModels.load();
		hospital = models.schema;
		morning = models.situation("Morning");
	}

	/** A planner that drops the first action of its first {@code corruptions} plans. */
	private static GoalPlanner corrupting(int corruptions) {
		SchemaGoalPlanner real = new SchemaGoalPlanner(new GoalSolver(hospital));
		AtomicInteger calls = new AtomicInteger();
		return (goal, from) -> {
			PlanningOutcome outcome = real.plan(goal, from);
			if (outcome instanceof PlanningOutcome.Planned p && calls.getAndIncrement() < corruptions && !p.plan().isEmpty()) {
				return new PlanningOutcome.Planned(new Plan(p.plan().actions().subList(1, p.plan().size())));
			}
			return outcome;
		};
	}

	private static List<String> run(int corruptions) {
		DryRunWorld world = new DryRunWorld(hospital, morning);
		VerifiedHospital app = new VerifiedHospital(world, corrupting(corruptions), world, new SchemaPlanCheck(hospital));
		List<String> log = new ArrayList<>();
		app.status.observe(s -> log.add(s.toString()));
		try (DeterministicScheduler scheduler = Scheduler.deterministic()) {
			scheduler.deploy(app);
			scheduler.send(app.request, new ModelTask(hospital, "GoTo", List.of(morning.object("ward3").orElseThrow())));
			scheduler.runToCompletion();
			assertTrue(scheduler.unhandledFaults().isEmpty(), () -> "unhandled " + scheduler.unhandledFaults());
		}
		return log;
	}

	@Test
	void corruptedPlanIsRefutedAndReplanned() {
		List<String> log = run(1);
		assertEquals("task GoTo(ward3) completed", log.get(log.size() - 1), String.join("\n", log));
		assertEquals(1, log.stream().filter(l -> l.startsWith("replanning IsAt(ward3) (1 of 3)") && l.contains("precondition")).count(),
				String.join("\n", log));
		assertTrue(log.stream().noneMatch(l -> l.contains("Courier.move(c4, c5) started") && log.indexOf(l) < 2));
	}

	@Test
	void plannerThatAlwaysCorruptsEndsInRemoteOperation() {
		List<String> log = run(Integer.MAX_VALUE);
		assertTrue(log.get(log.size() - 1).startsWith("remote operation requested for task GoTo(ward3)"), String.join("\n", log));
		assertEquals(3, log.stream().filter(l -> l.startsWith("replanning")).count());
		assertTrue(log.stream().noneMatch(l -> l.contains("started") && l.startsWith("action")), "no corrupted action may run");
	}
}
