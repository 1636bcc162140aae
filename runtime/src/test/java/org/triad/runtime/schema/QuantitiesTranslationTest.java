package org.triad.runtime.schema;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;

/**
 * Numbers the planner computes with: arithmetic evaluated as the models mean it (int while it fits, a
 * division by zero or an overflow a model fault that names the expression), and a quantity a robot reports
 * as NaN refused by the translation with the atom named, never planned with.
 */
class QuantitiesTranslationTest {
	private static final Expr BATTERY = Expr.call("Bot", "battery");

	private static final AppSchema SCHEMA = AppSchema.builder("Yard", "Bot", "World")
			.property(new PropertySchema("Bot", "battery", List.of(), "double"))
			.action(new ActionSchema("Bot", "drain", List.of(), new Expr.Compare(Expr.Op.GT, BATTERY, new Expr.Lit(1)),
					List.of(new Effect((Expr.Call) BATTERY, true, new Expr.Arith('/', BATTERY, new Expr.Arith('-', BATTERY, BATTERY)))),
					new Expr.Lit(2)))
			.goal(new GoalSchema("Low", List.of(), new Expr.Compare(Expr.Op.LT, BATTERY, new Expr.Lit(5))))
			.build();

	@Test
	void arithmeticIsEvaluatedAsTheModelsMeanIt() {
		assertEquals(7, Evaluator.arithmetic(new Expr.Arith('+', new Expr.Lit(3), new Expr.Lit(4)), 3, 4));
		assertEquals(3.5, Evaluator.arithmetic(new Expr.Arith('/', new Expr.Lit(7), new Expr.Lit(2)), 7, 2));
		assertEquals(4294967296.0, Evaluator.arithmetic(new Expr.Arith('*', new Expr.Lit(65536), new Expr.Lit(65536)), 65536, 65536));
		assertEquals("3 - (2 - 1) * 4", Exprs.show(new Expr.Arith('-', new Expr.Lit(3),
				new Expr.Arith('*', new Expr.Arith('-', new Expr.Lit(2), new Expr.Lit(1)), new Expr.Lit(4)))));
	}

	@Test
	void aDivisionByZeroInTheDryWorldIsAModelFaultNamingTheExpression() {
		State s = State.builder().value(Atom.of("Bot", "battery"), 10.0).build();
		ModelEvaluationException e = assertThrows(ModelEvaluationException.class,
				() -> new Transitions(SCHEMA).apply(new GroundAction("Bot", "drain", List.of()), s));
		assertEquals("division by zero: Bot.battery() / (Bot.battery() - Bot.battery())", e.getMessage());
		ModelEvaluationException overflow = assertThrows(ModelEvaluationException.class,
				() -> Evaluator.arithmetic(new Expr.Arith('*', BATTERY, BATTERY), 1e200, 1e200));
		assertTrue(overflow.getMessage().startsWith("overflow: Bot.battery() * Bot.battery()"), overflow.getMessage());
	}

	@Test
	void aQuantityReportedAsNaNIsRefusedWithItsAtom() {
		State s = State.builder().value(Atom.of("Bot", "battery"), Double.NaN).build();
		PddlTranslationException e = assertThrows(PddlTranslationException.class,
				() -> new PddlTranslator(SCHEMA).translate(s, SCHEMA.goal("Low").orElseThrow(), Map.of()));
		assertTrue(e.getMessage().contains("is NaN in the state"), e.getMessage());
		GoalSolver.Outcome o = new GoalSolver(SCHEMA).plan("Low", List.of(), s);
		assertTrue(o.failure().contains("NaN"), o.failure());
	}
}
