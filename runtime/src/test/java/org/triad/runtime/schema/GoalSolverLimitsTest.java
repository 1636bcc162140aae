package org.triad.runtime.schema;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GenericObject;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * RefArc's planner component keeps the engine's bounds per goal: a goal whose task is too large for
 * the memory fails that goal with one message naming the phase and the size (what the Status port
 * then says), in a moment and without an OutOfMemoryError, and the same planner plans the next goal.
 */
class GoalSolverLimitsTest {
	private static final Expr A = Expr.var("a");
	private static final Expr B = Expr.var("b");
	private static final Expr C = Expr.var("c");

	/** A bot that can mark any three places (no precondition binds them) and walk between adjacent ones. */
	private static final AppSchema SCHEMA = AppSchema.builder("Marks", "Bot", "World")
			.type(TypeSchema.ofClass("Place", null, false))
			.property(new PropertySchema("Bot", "loc", List.of(), "Place"))
			.property(new PropertySchema("World", "adj", List.of(new Param("a", "Place"), new Param("b", "Place")), "boolean"))
			.property(new PropertySchema("World", "marked", List.of(new Param("a", "Place"), new Param("b", "Place"), new Param("c", "Place")),
					"boolean"))
			.action(new ActionSchema("Bot", "mark", List.of(new Param("a", "Place"), new Param("b", "Place"), new Param("c", "Place")),
					new Expr.Lit(true), List.of(new Effect((Expr.Call) Expr.call("World", "marked", A, B, C), true, null))))
			.action(new ActionSchema("Bot", "move", List.of(new Param("a", "Place"), new Param("b", "Place")),
					Expr.and(Expr.eq(Expr.call("Bot", "loc"), A), Expr.call("World", "adj", A, B)),
					List.of(new Effect((Expr.Call) Expr.call("Bot", "loc"), true, B))))
			.goal(new GoalSchema("Marked", List.of(new Param("a", "Place"), new Param("b", "Place"), new Param("c", "Place")),
					Expr.call("World", "marked", A, B, C)))
			.goal(new GoalSchema("At", List.of(new Param("a", "Place")), Expr.eq(Expr.call("Bot", "loc"), A)))
			.build();

	@Test
	void aGoalTooLargeForTheMemoryFailsThatGoalAndTheNextOneIsPlanned() {
		State.Builder world = State.builder();
		int n = 3000;
		GenericObject[] places = new GenericObject[n];
		for (int i = 0; i < n; i++) {
			places[i] = new GenericObject("p" + i, "Place", Map.of());
			world.object(places[i]);
		}
		world.value(Atom.of("Bot", "loc"), places[0]).fact(Atom.of("World", "adj", places[0], places[1]));
		State from = world.build();
		GoalSolver solver = new GoalSolver(SCHEMA);

		GoalSolver.Outcome huge = solver.plan("Marked", List.of(places[1], places[2], places[3]), from);
		assertFalse(huge.planned());
		// the phase and the size, in one line (3,000³ = 2.7·10¹⁰ instances of 'mark')
		assertTrue(huge.failure().startsWith("planner error: grounding would create 3·10¹⁰ actions of 'bot-mark' (3 parameters no precondition"
				+ " binds, 3,000 objects each)"), huge.failure());
		assertEquals(1, huge.failure().lines().count(), huge.failure());

		// every goal on that world is as large (the translation keeps every action); on a smaller one
		// the same solver plans again
		State small = State.builder().object(places[0]).object(places[1]).object(places[2]).value(Atom.of("Bot", "loc"), places[0])
				.fact(Atom.of("World", "adj", places[0], places[1])).build();
		GoalSolver.Outcome walk = solver.plan("At", List.of(places[1]), small);
		assertNull(walk.failure());
		assertEquals(List.of(new GroundAction("Bot", "move", List.of(places[0], places[1]))), walk.plan().actions());
	}
}
