package org.triad.runtime.schema;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
 * The congestion hook ({@link GoalSolver#withCosts}): a move whose corridor others queue for costs its expected
 * wait, and the plan takes the free side of the ring; without costs the shortest plan, as before.
 */
class CongestionCostTest {
	private static final Expr LOC = Expr.call("Bot", "loc");

	private static final AppSchema SCHEMA = AppSchema.builder("Ring", "Bot", "World")
			.type(TypeSchema.ofClass("Place", null, false))
			.property(new PropertySchema("Bot", "loc", List.of(), "Place"))
			.property(new PropertySchema("World", "adj", List.of(new Param("a", "Place"), new Param("b", "Place")), "boolean"))
			.action(new ActionSchema("Bot", "move", List.of(new Param("src", "Place"), new Param("dst", "Place")),
					Expr.and(Expr.eq(LOC, Expr.var("src")), Expr.call("World", "adj", Expr.var("src"), Expr.var("dst"))),
					List.of(new Effect((Expr.Call) LOC, true, Expr.var("dst")))))
			.goal(new GoalSchema("At", List.of(new Param("p", "Place")), Expr.eq(LOC, Expr.var("p"))))
			.build();

	private final GenericObject hall = new GenericObject("hall", "Place", Map.of());
	private final GenericObject west = new GenericObject("west", "Place", Map.of());
	private final GenericObject east = new GenericObject("east", "Place", Map.of());
	private final GenericObject ward = new GenericObject("ward", "Place", Map.of());

	/** The bot in the hall; the ward two steps away round either side of the ring, west or east. */
	private State ring() {
		State.Builder b = State.builder().object(hall).object(west).object(east).object(ward).value(Atom.of("Bot", "loc"), hall);
		for (GenericObject[] e : new GenericObject[][] { { hall, west }, { west, ward }, { hall, east }, { east, ward } }) {
			b.fact(Atom.of("World", "adj", e[0], e[1])).fact(Atom.of("World", "adj", e[1], e[0]));
		}
		return b.build();
	}

	private List<GroundAction> plan(GoalSolver solver) {
		GoalSolver.Outcome o = solver.plan("At", List.of(ward), ring());
		assertNull(o.failure());
		PlanChecker.Verdict v = new PlanChecker(SCHEMA).check(ring(), o.plan(), new ModelGoal(SCHEMA, "At", List.of(ward)));
		assertTrue(v.valid(), v.reason());
		return o.plan().actions();
	}

	/** Expected wait (in steps) of a move into {@code congested}. */
	private static ActionCosts waitingAt(GenericObject congested, double steps) {
		return a -> a.args().get(1) == congested ? steps : 0;
	}

	@Test
	void aCongestedSideOfTheRingMakesThePlanTakeTheOther() {
		List<GroundAction> viaWest = List.of(new GroundAction("Bot", "move", List.of(hall, west)), new GroundAction("Bot", "move", List.of(west, ward)));
		List<GroundAction> viaEast = List.of(new GroundAction("Bot", "move", List.of(hall, east)), new GroundAction("Bot", "move", List.of(east, ward)));
		GoalSolver solver = new GoalSolver(SCHEMA);
		assertEquals(viaEast, plan(solver.withCosts(waitingAt(west, 6))), "the west corridor is congested");
		assertEquals(viaWest, plan(solver.withCosts(waitingAt(east, 6))), "the east corridor is congested");
		assertEquals(2, plan(solver).size(), "without costs: a shortest plan");
		// a wait smaller than the detour's extra steps (none here: both sides are two steps) still decides
		assertEquals(viaEast, plan(solver.withCosts(waitingAt(west, 0.5))));
	}

	@Test
	void aCostThatIsNotAFiniteNumberIsAClearFailureNotACrash() {
		GoalSolver.Outcome o = new GoalSolver(SCHEMA).withCosts(a -> Double.NaN).plan("At", List.of(ward), ring());
		assertTrue(o.failure() != null && o.failure().contains("a cost is a finite number"), String.valueOf(o.failure()));
	}
}
