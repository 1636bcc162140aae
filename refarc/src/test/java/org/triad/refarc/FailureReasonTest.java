package org.triad.refarc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.Plan;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;

/** When the platform can say why an action failed, the reason is on Status with the failure and the re-planning. */
class FailureReasonTest {

	@Test
	void thePlatformsReasonReachesStatus() {
		AtomicBoolean done = new AtomicBoolean();
		AtomicBoolean failedOnce = new AtomicBoolean();
		GoalInstance goal = new GoalInstance() {
			@Override
			public String name() {
				return "Done";
			}

			@Override
			public List<Object> args() {
				return List.of();
			}

			@Override
			public boolean isSatisfiedIn(State state) {
				return done.get();
			}
		};
		TaskInstance task = new TaskInstance() {
			@Override
			public String name() {
				return "Do";
			}

			@Override
			public List<Object> args() {
				return List.of();
			}

			@Override
			public List<GoalInstance> goals() {
				return List.of(goal);
			}
		};
		GroundAction open = new GroundAction("robot", "open", List.of());
		ActionRunner runner = new ActionRunner() {
			@Override
			public Optional<String> violatedPrecondition(GroundAction action, State now) {
				return Optional.empty();
			}

			@Override
			public boolean execute(GroundAction action) {
				if (failedOnce.compareAndSet(false, true)) {
					return false;
				}
				done.set(true);
				return true;
			}

			@Override
			public Optional<String> failureReason(GroundAction action) {
				return Optional.of("DOOR_CLOSED: the fire door is closed");
			}
		};
		RefArcRun run = new RefArcRunner(() -> State.builder().build(), (g, from) -> new PlanningOutcome.Planned(new Plan(List.of(open))),
				runner).run(task);
		assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), () -> run.log().toString());
		List<String> lines = run.statuses().stream().map(Object::toString).toList();
		assertTrue(lines.contains("action robot.open() failed: the platform reported failure: DOOR_CLOSED: the fire door is closed"),
				lines::toString);
		assertTrue(lines.stream().anyMatch(l -> l.startsWith("replanning Done() (1 of 3)") && l.endsWith("DOOR_CLOSED: the fire door is closed")),
				lines::toString);
	}

	/**
	 * The abort carries the kind of the failure that ended it: the building's congestion when the last action failed so
	 * (a fleet queues such a task again), a fault otherwise; the row's first congested failure does not make a later fault one.
	 */
	@Test
	void theAbortCarriesTheCauseOfTheFailureThatEndedIt() {
		assertEquals(Failure.Cause.CONGESTION, abortCause(List.of(Failure.Cause.FAULT, Failure.Cause.CONGESTION, Failure.Cause.CONGESTION,
				Failure.Cause.CONGESTION)));
		assertEquals(Failure.Cause.FAULT, abortCause(List.of(Failure.Cause.CONGESTION, Failure.Cause.CONGESTION, Failure.Cause.CONGESTION,
				Failure.Cause.FAULT)));
	}

	/** Runs a one-action task whose action fails with these causes in turn (one per try, 1 + 3 re-plans); the abort's cause. */
	private static Failure.Cause abortCause(List<Failure.Cause> causes) {
		java.util.concurrent.atomic.AtomicInteger tries = new java.util.concurrent.atomic.AtomicInteger();
		GoalInstance goal = new GoalInstance() {
			@Override
			public String name() {
				return "Done";
			}

			@Override
			public List<Object> args() {
				return List.of();
			}

			@Override
			public boolean isSatisfiedIn(State state) {
				return false;
			}
		};
		TaskInstance task = new TaskInstance() {
			@Override
			public String name() {
				return "Do";
			}

			@Override
			public List<Object> args() {
				return List.of();
			}

			@Override
			public List<GoalInstance> goals() {
				return List.of(goal);
			}
		};
		ActionRunner runner = new ActionRunner() {
			@Override
			public Optional<String> violatedPrecondition(GroundAction action, State now) {
				return Optional.empty();
			}

			@Override
			public boolean execute(GroundAction action) {
				tries.incrementAndGet();
				return false;
			}

			@Override
			public Optional<Failure> failure(GroundAction action) {
				return Optional.of(new Failure("try " + tries.get(), causes.get(tries.get() - 1)));
			}
		};
		RefArcRun run = new RefArcRunner(() -> State.builder().build(),
				(g, from) -> new PlanningOutcome.Planned(new Plan(List.of(new GroundAction("robot", "drive", List.of())))), runner).run(task);
		assertEquals(RefArcRun.Outcome.ABORTED, run.outcome(), () -> run.log().toString());
		Status.TaskAborted aborted = run.statuses().stream().filter(Status.TaskAborted.class::isInstance).map(Status.TaskAborted.class::cast)
				.findFirst().orElseThrow();
		assertTrue(aborted.reason().contains("try 4"), aborted.reason());
		return aborted.cause();
	}
}
