package org.triad.runtime.schema;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GenericObject;
import org.triad.runtime.app.GroundAction;

/** The executor's typed dispatch: conversions, and refusals that name the action. */
class ActionTableTest {
	enum Speed { SLOW, FAST }

	private static final AppSchema SCHEMA = AppSchema.builder("Shop", "Bot", "World")
			.action(new ActionSchema("Bot", "move", List.of(new Param("to", "Place"), new Param("speed", "Speed")), Expr.TRUE, List.of()))
			.action(new ActionSchema("Bot", "charge", List.of(new Param("amount", "double")), Expr.TRUE, List.of()))
			.action(new ActionSchema("World", "tick", List.of(), Expr.TRUE, List.of()))
			.build();

	private final List<String> calls = new ArrayList<>();
	private final GenericObject hall = new GenericObject("hall", "Place", Map.of());

	private boolean move(GenericObject to, Speed speed) {
		calls.add("move " + to.name() + " " + speed);
		return true;
	}

	private boolean charge(double amount) {
		calls.add("charge " + amount);
		return amount > 0;
	}

	private ActionTable table() {
		return ActionTable.builder(SCHEMA)
				.action("Bot", "move", GenericObject.class, Speed.class, this::move)
				.action("Bot", "charge", Double.class, this::charge)
				.action("World", "tick", () -> calls.add("tick"))
				.build();
	}

	@Test
	void argumentsReachTheMethodsConverted() {
		ActionTable t = table();
		assertTrue(t.execute(new GroundAction("Bot", "move", List.of(hall, new EnumValue("Speed", "FAST")))));
		assertEquals(false, t.execute(new GroundAction("Bot", "charge", List.of(0))));
		assertTrue(t.execute(new GroundAction("World", "tick", List.of())));
		assertEquals(List.of("move hall FAST", "charge 0.0", "tick"), calls);
	}

	@Test
	void aWrongArgumentIsRefusedNamingTheAction() {
		IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
				() -> table().execute(new GroundAction("Bot", "move", List.of("hall", new EnumValue("Speed", "FAST")))));
		assertEquals("argument 1 of Bot.move(hall, Speed.FAST) is not a GenericObject: hall (java.lang.String)", e.getMessage());
		assertEquals("Bot.charge(1, 2) has 2 argument(s), the action takes 1",
				assertThrows(IllegalArgumentException.class, () -> table().execute(new GroundAction("Bot", "charge", List.of(1, 2)))).getMessage());
		assertEquals("no method for action Bot.fly()",
				assertThrows(IllegalArgumentException.class, () -> table().execute(new GroundAction("Bot", "fly", List.of()))).getMessage());
	}

	@Test
	void theTableMatchesTheSchema() {
		assertEquals("no method for the actions [World.tick]", assertThrows(IllegalStateException.class,
				() -> ActionTable.builder(SCHEMA).action("Bot", "move", GenericObject.class, Speed.class, this::move)
						.action("Bot", "charge", Double.class, this::charge).build()).getMessage());
		assertEquals("action Bot.charge takes 1 argument(s), the method 0", assertThrows(IllegalArgumentException.class,
				() -> ActionTable.builder(SCHEMA).action("Bot", "charge", () -> true)).getMessage());
		assertEquals("the application has no action Bot.fly", assertThrows(IllegalArgumentException.class,
				() -> ActionTable.builder(SCHEMA).action("Bot", "fly", () -> true)).getMessage());
	}
}
