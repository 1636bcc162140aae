package org.triad.generator.java;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.triad.generator.java.JavaGeneratorTest.goal;
import static org.triad.generator.java.JavaGeneratorTest.schemaOf;
import static org.triad.generator.java.JavaGeneratorTest.situation;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.generator.SchemaBuilder;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.EnumValue;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.AppSchema;

/**
 * Generated Java for a model with enums, every built-in type, Java keywords as names and names
 * that clash with generated or imported classes (test model {@code models/workshop}).
 */
class WorkshopGeneratorTest {
	@TempDir
	static Path tmp;
	static GeneratedCode workshop;

	@BeforeAll
	static void generateAndCompile() throws Exception {
		workshop = GeneratedCode.of(Path.of("src/test/resources/models/workshop"), tmp);
	}

	@Test
	void compilesWithoutWarnings() {
		workshop.assertCompiledCleanly();
	}

	@Test
	void schemaEqualsTheSchemaBuiltFromTheModels() throws Exception {
		AppSchema expected = SchemaBuilder.build(workshop.loaded.application());
		AppSchema generated = schemaOf(workshop);
		assertEquals(expected.types(), generated.types());
		assertEquals(expected.properties(), generated.properties());
		assertEquals(expected.actions(), generated.actions());
		assertEquals(expected.goals(), generated.goals());
	}

	@Test
	void enumsAndAttributesOfEveryBuiltInType() throws Exception {
		Class<?> color = workshop.load("domain.Color");
		assertTrue(color.isEnum());
		assertEquals(List.of("RED", "GREEN"), java.util.Arrays.stream(color.getEnumConstants()).map(c -> ((Enum<?>) c).name()).toList());
		Class<?> bolt = workshop.load("domain.Bolt");
		Object b = bolt.getConstructor(String.class).newInstance("b1");
		Object green = color.getEnumConstants()[1];
		bolt.getMethod("setColor", color).invoke(b, green);
		bolt.getMethod("setMass", double.class).invoke(b, 0.25);
		bolt.getMethod("setFragile", boolean.class).invoke(b, true);
		assertEquals(green, bolt.getMethod("getColor").invoke(b));
		assertEquals(0.25, bolt.getMethod("getMass").invoke(b));
		assertEquals(true, bolt.getMethod("isFragile").invoke(b));
		assertEquals(List.class, workshop.load("IWorld").getMethod("allLists").getReturnType(), "the world has a property lists");
		assertEquals("IsAt", ((DomainObject) workshop.load("domain.IsAt").getConstructor(String.class).newInstance("m")).typeName());
	}

	@Test
	void stateProviderObservesEnumAndBooleanArgumentsButNotNumbers() throws Exception {
		State bench = situation(workshop, "Bench");
		StateBackedActors actors = new StateBackedActors(workshop, schemaOf(workshop), bench);
		StateSource provider = (StateSource) workshop.load("WorkshopStateProvider").getConstructors()[0].newInstance(actors.robot, actors.world);
		assertEquals(bench, provider.currentState());
		assertTrue(workshop.source("WorkshopStateProvider").contains("// Arm.counted is not observed: its n cannot be enumerated."));
	}

	@Test
	void situationsStoreIntLiteralsOfDoublesAsDoubles() {
		State bench = situation(workshop, "Bench");
		assertEquals(Optional.of(2.0), bench.valueOf(new org.triad.runtime.app.Atom("Arm", "reach", List.of(new EnumValue("Color", "GREEN")))));
		assertEquals(1.0, ((org.triad.runtime.app.GenericObject) bench.object("b1").orElseThrow()).attributes().get("mass"));
		assertEquals(4, ((org.triad.runtime.app.GenericObject) bench.object("b1").orElseThrow()).attributes().get("size"));
	}

	@Test
	void actionExecutorConvertsArgumentsToTheirJavaTypes() throws Exception {
		State bench = situation(workshop, "Bench");
		StateBackedActors actors = new StateBackedActors(workshop, schemaOf(workshop), bench);
		ActionRunner executor = (ActionRunner) workshop.load("WorkshopActionExecutor").getConstructors()[0].newInstance(actors.robot, actors.world);
		DomainObject b1 = actors.object("b1");
		GroundAction paintRed = new GroundAction("Arm", "paint", List.of(b1, new EnumValue("Color", "RED")));
		GroundAction paintGreen = new GroundAction("Arm", "paint", List.of(b1, new EnumValue("Color", "GREEN")));
		assertEquals(Optional.of("!Arm.painted(b, c)"), executor.violatedPrecondition(paintRed, bench));
		assertEquals(Optional.of("Arm.colorOf(b) != c"), executor.violatedPrecondition(paintGreen, bench));
		assertTrue(executor.execute(paintGreen));
		GroundAction setLoad = new GroundAction("Arm", "setLoad", List.of(5, 1, "x", true));
		assertEquals(Optional.empty(), executor.violatedPrecondition(setLoad, bench));
		assertTrue(executor.execute(setLoad));
		GroundAction create = new GroundAction("Arm", "new", List.of(actors.object("t1")));
		assertTrue(executor.execute(create));
		GroundAction restock = new GroundAction("Shop", "restock", List.of(actors.object("t1")));
		assertTrue(executor.execute(restock));
		// what the generated methods received: the Java enum constant, and 1 widened to a double
		Object green = workshop.load("domain.Color").getEnumConstants()[1];
		assertEquals(List.of(new GroundAction("Arm", "paint", List.of(b1, green)), new GroundAction("Arm", "setLoad", List.of(5, 1.0, "x", true)),
				create, restock), actors.executed);
	}

	@Test
	void tasksPassLiteralsToTheirGoals() throws Exception {
		TaskInstance load = (TaskInstance) workshop.load("tasks.Load").getConstructors()[0].newInstance(4);
		assertEquals(List.of(goal(workshop, "Heavy", 4, 2.5), goal(workshop, "Heavy", 3, 1.0)), load.goals());
		Object red = workshop.load("domain.Color").getEnumConstants()[0];
		DomainObject b1 = (DomainObject) workshop.load("domain.Bolt").getConstructor(String.class).newInstance("b1");
		DomainObject t2 = (DomainObject) workshop.load("domain.Tray").getConstructor(String.class).newInstance("t2");
		TaskInstance paint = (TaskInstance) workshop.load("tasks.Paint").getConstructors()[0].newInstance(b1, t2);
		State bench = situation(workshop, "Bench");
		assertEquals(List.of(true, false, true), paint.goals().stream().map(g -> g.isSatisfiedIn(bench)).toList());
		assertEquals(goal(workshop, "Painted", b1, red), paint.goals().get(0));
		assertTrue(goal(workshop, "Heavy", 3, 2.0).isSatisfiedIn(bench));
		assertFalse(goal(workshop, "Heavy", 3, 1.5).isSatisfiedIn(bench));
	}
}
