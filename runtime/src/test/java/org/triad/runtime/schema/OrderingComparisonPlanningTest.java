package org.triad.runtime.schema;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.planner.pddl.PddlParser;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GenericObject;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * Ordering comparisons ({@code <}, {@code <=}, {@code >}, {@code >=}) in preconditions and goals are
 * planned, not refused at run time: a battery read against a threshold, a goal on a number, and goal
 * conditions that read a property inside another (the case that once failed with "cannot be planned
 * with STRIPS").
 */
class OrderingComparisonPlanningTest {
	private static final Expr LOC = Expr.call("Bot", "loc");
	private static final Expr CHARGE = Expr.call("Bot", "charge");

	private static final AppSchema SCHEMA = AppSchema.builder("Yard", "Bot", "World")
			.type(TypeSchema.ofClass("Place", null, false))
			.property(new PropertySchema("Bot", "loc", List.of(), "Place"))
			.property(new PropertySchema("Bot", "charge", List.of(), "int"))
			.property(new PropertySchema("World", "adj", List.of(new Param("a", "Place"), new Param("b", "Place")), "boolean"))
			.property(new PropertySchema("World", "dock", List.of(new Param("p", "Place")), "boolean"))
			.property(new PropertySchema("World", "home", List.of(), "Place"))
			.action(new ActionSchema("Bot", "move", List.of(new Param("src", "Place"), new Param("dst", "Place")),
					Exprs.conjunction(List.of(Expr.eq(LOC, Expr.var("src")), Expr.call("World", "adj", Expr.var("src"), Expr.var("dst")),
							new Expr.Compare(Expr.Op.GE, CHARGE, new Expr.Lit(2)))),
					List.of(new Effect((Expr.Call) LOC, true, Expr.var("dst")), new Effect((Expr.Call) CHARGE, true, new Expr.Lit(1)))))
			.action(new ActionSchema("Bot", "recharge", List.of(),
					Expr.and(Expr.call("World", "dock", LOC), new Expr.Compare(Expr.Op.LT, CHARGE, new Expr.Lit(5))),
					List.of(new Effect((Expr.Call) CHARGE, true, new Expr.Lit(5)))))
			.goal(new GoalSchema("At", List.of(new Param("p", "Place")), Expr.eq(LOC, Expr.var("p"))))
			.goal(new GoalSchema("Charged", List.of(new Param("n", "int")), new Expr.Compare(Expr.Op.GT, CHARGE, Expr.var("n"))))
			.goal(new GoalSchema("Docked", List.of(), Expr.call("World", "dock", LOC)))
			.goal(new GoalSchema("Home", List.of(), Expr.eq(LOC, Expr.call("World", "home"))))
			.goal(new GoalSchema("Undocked", List.of(), Expr.eq(Expr.call("World", "dock", LOC), new Expr.Lit(false))))
			.goal(new GoalSchema("DockIs", List.of(new Param("d", "boolean")), Expr.eq(Expr.call("World", "dock", LOC), Expr.var("d"))))
			.build();

	private final GenericObject a = new GenericObject("a", "Place", Map.of());
	private final GenericObject b = new GenericObject("b", "Place", Map.of());
	private final GenericObject c = new GenericObject("c", "Place", Map.of());

	/** The bot at a (the dock) with charge 1; a-b-c in a line; home is c. */
	private State start() {
		return State.builder().object(a).object(b).object(c).value(Atom.of("Bot", "loc"), a).value(Atom.of("Bot", "charge"), 1)
				.fact(Atom.of("World", "adj", a, b)).fact(Atom.of("World", "adj", b, a)).fact(Atom.of("World", "adj", b, c))
				.fact(Atom.of("World", "dock", a)).value(Atom.of("World", "home"), c).build();
	}

	private List<GroundAction> planned(String goal, List<Object> args, State from) {
		GoalSolver.Outcome outcome = new GoalSolver(SCHEMA).plan(goal, args, from);
		assertNull(outcome.failure());
		PlanChecker.Verdict verdict = new PlanChecker(SCHEMA).check(from, outcome.plan(), new ModelGoal(SCHEMA, goal, args));
		assertTrue(verdict.valid(), verdict.reason());
		return outcome.plan().actions();
	}

	@Test
	void aThresholdInAPreconditionMakesTheRobotRechargeFirst() {
		assertEquals(List.of(new GroundAction("Bot", "recharge", List.of()), new GroundAction("Bot", "move", List.of(a, b))),
				planned("At", List.of(b), start()));
	}

	@Test
	void aGoalOnANumberIsPlanned() {
		assertEquals(List.of(new GroundAction("Bot", "recharge", List.of())), planned("Charged", List.of(4), start()));
		assertEquals(List.of(), planned("Charged", List.of(0), start()));
	}

	@Test
	void goalsThatReadAPropertyInsideAnotherArePlanned() {
		State atB = start().toBuilder().value(Atom.of("Bot", "loc"), b).build();
		assertEquals(List.of(new GroundAction("Bot", "move", List.of(b, a))), planned("Docked", List.of(), atB.toBuilder()
				.value(Atom.of("Bot", "charge"), 3).build()));
		assertEquals(List.of(new GroundAction("Bot", "move", List.of(b, c))), planned("Home", List.of(), atB.toBuilder()
				.value(Atom.of("Bot", "charge"), 2).build()));
	}

	@Test
	void aConditionComparedWithATruthValueIsPlanned() {
		State charged = start().toBuilder().value(Atom.of("Bot", "charge"), 3).build();
		List<GroundAction> away = List.of(new GroundAction("Bot", "move", List.of(a, b)));
		assertEquals(away, planned("Undocked", List.of(), charged));
		assertEquals(away, planned("DockIs", List.of(false), charged));
		assertEquals(List.of(), planned("DockIs", List.of(true), charged));
	}

	@Test
	void anUnreachableThresholdIsExplainedInTheModelsTerms() {
		State stranded = start().toBuilder().value(Atom.of("Bot", "loc"), b).build();
		GoalSolver.Outcome outcome = new GoalSolver(SCHEMA).plan("At", List.of(c), stranded);
		assertEquals(null, outcome.plan());
		assertTrue(outcome.failure().startsWith("no plan"), outcome.failure());
	}

	@Test
	void theTextOfATranslationWithOrderingsParsesBackToIt() {
		var task = new GoalSolver(SCHEMA).translator().translate(start(), SCHEMA.goal("Charged").orElseThrow(), Map.of("n", 4));
		assertEquals(task.domain(), PddlParser.parseDomain(task.domainText(), "domain.pddl"), task.domainText());
		assertEquals(task.problem(), PddlParser.parseProblem(task.problemText(), "problem.pddl"), task.problemText());
		assertTrue(task.problemText().contains("(triad-less int-1 int-5)"), task.problemText());
	}
}
