package org.triad.examples.logistics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.schema.Transitions;

import generated.logisticsdomain.LogisticsDomainActionExecutor;
import generated.logisticsdomain.LogisticsDomainSchema;
import generated.logisticsdomain.LogisticsDomainStateProvider;
import generated.logisticsdomain.domain.Room;
import generated.logisticsdomain.domain.WayPoint;
import generated.logisticsdomain.tasks.GoTo;

/** The generated behaviours driving the handcrafted robot and world: what they observe and do agrees with the models. */
class LogisticsApplicationTest {
	private final FloorPlan floor = new FloorPlan();
	private final WayPoint c1 = floor.wayPoint("c1");
	private final WayPoint c2 = floor.wayPoint("c2");
	private final Room office = floor.room("office", "Office");
	private final Room lab = floor.room("lab", "Lab");
	private final LogisticsRobot robot = new LogisticsRobot(floor.connect(office, c1).connect(c1, c2).connect(c2, lab), office);
	private final LogisticsDomainStateProvider provider = new LogisticsDomainStateProvider(robot, floor);
	private final LogisticsDomainActionExecutor executor = new LogisticsDomainActionExecutor(robot, floor);

	@Test
	void stateProviderObservesRobotAndWorld() {
		State s = provider.currentState();
		assertEquals(List.of("c1", "c2", "office", "lab"), List.copyOf(s.objects().keySet()));
		assertEquals(Optional.of(office), s.valueOf(Atom.of("LogisticsRobot", "loc")));
		assertTrue(s.holds(Atom.of("RoomsWorld", "adj", c2, lab)));
		assertFalse(s.holds(Atom.of("RoomsWorld", "adj", office, lab)));
		assertEquals(7, s.values().size(), "loc and six directed connections");
	}

	@Test
	void executedActionsChangeTheWorldAsTheirPostconditionsSay() {
		Transitions transitions = new Transitions(LogisticsDomainSchema.SCHEMA);
		GroundAction move = new GroundAction("LogisticsRobot", "move", List.of(office, c1));
		State before = provider.currentState();
		assertEquals(Optional.empty(), executor.violatedPrecondition(move, before));
		assertTrue(executor.execute(move));
		assertEquals(transitions.apply(move, before), provider.currentState());

		GroundAction jump = new GroundAction("LogisticsRobot", "move", List.of(c1, lab));
		assertEquals(Optional.of("RoomsWorld.adj(src, dst)"), executor.violatedPrecondition(jump, provider.currentState()));
		assertFalse(executor.execute(jump), "the robot refuses, as its implementation says");
	}

	@Test
	void taskGoalsAreJudgedOnObservedStates() {
		GoTo task = new GoTo(office, lab);
		assertEquals(List.of(true, false), task.goals().stream().map(g -> g.isSatisfiedIn(provider.currentState())).toList());
		executor.execute(new GroundAction("LogisticsRobot", "move", List.of(office, c1)));
		executor.execute(new GroundAction("LogisticsRobot", "move", List.of(c1, c2)));
		executor.execute(new GroundAction("LogisticsRobot", "move", List.of(c2, lab)));
		assertEquals(List.of(false, true), task.goals().stream().map(g -> g.isSatisfiedIn(provider.currentState())).toList());
	}
}
