package org.triad.generator.java;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.triad.Situation;
import org.triad.generator.SchemaBuilder;
import org.triad.generator.SituationReader;
import org.triad.refarc.ActionRunner;
import org.triad.refarc.StateSource;
import org.triad.runtime.app.DomainObject;
import org.triad.runtime.app.GenericObject;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.GroundAction;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.AppSchema;

/** Generates Java for the example applications, compiles it with every warning an error, and runs it. */
class JavaGeneratorTest {
	@TempDir
	static Path tmp;
	static GeneratedCode logistics;
	static GeneratedCode hospital;

	@BeforeAll
	static void generateAndCompile() throws Exception {
		logistics = GeneratedCode.of(Path.of("../models/logistics/src/main/models"), tmp.resolve("logistics"));
		hospital = GeneratedCode.of(Path.of("../models/hospital/src/main/models"), tmp.resolve("hospital"));
	}

	@Test
	void generatedCodeCompilesWithoutWarnings() {
		logistics.assertCompiledCleanly();
		hospital.assertCompiledCleanly();
	}

	/** The one expected-text test: the paper's Fig. 4 for Listing 1, with the javadoc written from the model. */
	@Test
	void robotInterfaceOfListing1IsThePapers() throws Exception {
		assertEquals("""
				package generated.logisticsdomain;

				import generated.logisticsdomain.domain.WayPoint;

				/** The robot {@code LogisticsRobot}: implement it for a platform. Generated: do not edit. */
				public interface IRobot {
					/**
					 * Action {@code move(src, dst)} of robot {@code LogisticsRobot}: carry it out on the platform and return when it has ended.
					 * RefArc calls it only when its precondition holds: {@code loc() == src && RoomsWorld.adj(src, dst)}.
					 * Return {@code true} when it succeeded, so that afterwards {@code loc() == dst} holds as the properties report it;
					 * {@code false} when it failed (RefArc then observes the state again and re-plans). Do not throw for a failure.
					 */
					boolean move(WayPoint src, WayPoint dst);

					/**
					 * The current value of {@code loc()} (property of robot {@code LogisticsRobot}, of type {@code WayPoint}), as observed on the platform;
					 * an object must be one that {@code IWorld} lists; {@code null} when it has no value.
					 * Called whenever RefArc observes the state: answer quickly and without side effects.
					 */
					WayPoint loc();
				}
				""", logistics.source("IRobot"));
	}

	@Test
	void generatedSchemaEqualsTheSchemaBuiltFromTheModels() throws Exception {
		for (GeneratedCode code : List.of(logistics, hospital)) {
			AppSchema expected = SchemaBuilder.build(code.loaded.application());
			AppSchema generated = schemaOf(code);
			assertEquals(expected.name(), generated.name());
			assertEquals(expected.robot(), generated.robot());
			assertEquals(expected.world(), generated.world());
			assertEquals(expected.types(), generated.types());
			assertEquals(expected.properties(), generated.properties());
			assertEquals(expected.actions(), generated.actions());
			assertEquals(expected.goals(), generated.goals());
			assertEquals(expected.tasks(), generated.tasks());
		}
	}

	@Test
	void domainClassesFollowTheClassDiagram() throws Exception {
		Class<?> wayPoint = hospital.load("domain.WayPoint");
		Class<?> room = hospital.load("domain.Room");
		Class<?> thing = hospital.load("domain.Thing");
		Class<?> item = hospital.load("domain.Item");
		assertEquals(DomainObject.class, wayPoint.getSuperclass());
		assertEquals(wayPoint, room.getSuperclass());
		assertEquals(thing, item.getSuperclass());
		assertTrue(Modifier.isAbstract(thing.getModifiers()));
		assertFalse(Modifier.isAbstract(item.getModifiers()));

		DomainObject gauze = (DomainObject) item.getConstructor(String.class).newInstance("gauze");
		item.getMethod("setWeight", int.class).invoke(gauze, 3);
		item.getMethod("setLabel", String.class).invoke(gauze, "sterile gauze");
		assertEquals(3, item.getMethod("getWeight").invoke(gauze));
		assertEquals("sterile gauze", item.getMethod("getLabel").invoke(gauze));
		assertEquals("Item", gauze.typeName());
		assertEquals("gauze", gauze.name());
		assertEquals(new GenericObject("gauze", "Item", java.util.Map.of()), gauze);
		assertEquals("WayPoint", ((DomainObject) wayPoint.getConstructor(String.class).newInstance("c1")).typeName());
	}

	@Test
	void worldInterfaceListsTheObjectsOfEveryConcreteClass() throws Exception {
		Class<?> world = hospital.load("IWorld");
		for (String m : List.of("wayPoints", "rooms", "items", "persons")) {
			assertEquals(List.class, world.getMethod(m).getReturnType(), m);
		}
		assertThrows(NoSuchMethodException.class, () -> world.getMethod("things"), "Thing is abstract");
		assertEquals(boolean.class, world.getMethod("adj", hospital.load("domain.WayPoint"), hospital.load("domain.WayPoint")).getReturnType());
		assertEquals(hospital.load("domain.WayPoint"), world.getMethod("personAt", hospital.load("domain.Person")).getReturnType());
		assertEquals(boolean.class, world.getMethod("walk", hospital.load("domain.Person"), hospital.load("domain.WayPoint"),
				hospital.load("domain.WayPoint")).getReturnType());
	}

	@Test
	void goalsEvaluateTheirConditionInASituation() throws Exception {
		State morning = situation(hospital, "Morning");
		DomainObject lobby = object(hospital, "Room", "lobby");
		DomainObject storage = object(hospital, "Room", "storage");
		DomainObject gauze = object(hospital, "Item", "gauze");
		DomainObject alice = object(hospital, "Person", "alice");

		assertTrue(goal(hospital, "IsAt", lobby).isSatisfiedIn(morning));
		assertFalse(goal(hospital, "IsAt", storage).isSatisfiedIn(morning));
		assertTrue(goal(hospital, "Delivered", gauze, storage).isSatisfiedIn(morning));
		assertFalse(goal(hospital, "Delivered", gauze, lobby).isSatisfiedIn(morning));
		assertFalse(goal(hospital, "Holds", gauze).isSatisfiedIn(morning));
		assertTrue(goal(hospital, "PersonAt", alice, lobby).isSatisfiedIn(morning));
		assertFalse(goal(hospital, "PersonAt", alice, storage).isSatisfiedIn(morning));

		GoalInstance delivered = goal(hospital, "Delivered", gauze, storage);
		assertEquals("Delivered", delivered.name());
		assertEquals(List.of(gauze, storage), delivered.args());
		assertEquals("Delivered(gauze, storage)", delivered.describe());
	}

	@Test
	void goalsRejectMissingArguments() throws Exception {
		Constructor<?> c = hospital.load("goals.Holds").getConstructors()[0];
		InvocationTargetException e = assertThrows(InvocationTargetException.class, () -> c.newInstance((Object) null));
		assertTrue(e.getCause() instanceof NullPointerException);
	}

	@Test
	void tasksInstantiateTheirGoalsInOrder() throws Exception {
		DomainObject gauze = object(hospital, "Item", "gauze");
		DomainObject storage = object(hospital, "Room", "storage");
		DomainObject ward3 = object(hospital, "Room", "ward3");
		Class<?> fetch = hospital.load("tasks.Fetch");
		TaskInstance task = (TaskInstance) fetch.getConstructors()[0].newInstance(gauze, storage, ward3);
		assertEquals("Fetch", task.name());
		assertEquals(List.of(gauze, storage, ward3), task.args());
		assertEquals(List.of(goal(hospital, "IsAt", storage), goal(hospital, "Holds", gauze), goal(hospital, "IsAt", ward3)), task.goals());

		DomainObject office = object(logistics, "Room", "office");
		DomainObject lab = object(logistics, "Room", "lab");
		TaskInstance goTo = (TaskInstance) logistics.load("tasks.GoTo").getConstructors()[0].newInstance(office, lab);
		assertEquals(List.of("IsAt(office)", "IsAt(lab)"), goTo.goals().stream().map(GoalInstance::describe).toList());
		State floor = situation(logistics, "Floor");
		assertTrue(goTo.goals().get(0).isSatisfiedIn(floor));
		assertFalse(goTo.goals().get(1).isSatisfiedIn(floor));
	}

	@Test
	void stateProviderRebuildsTheSituationFromRobotAndWorld() throws Exception {
		for (Object[] app : new Object[][] { { logistics, "Floor" }, { hospital, "Morning" }, { hospital, "Evening" } }) {
			GeneratedCode code = (GeneratedCode) app[0];
			State expected = situation(code, (String) app[1]);
			StateBackedActors actors = new StateBackedActors(code, schemaOf(code), expected);
			StateSource provider = (StateSource) code.load(TriadNamesFor(code).stateProviderClass())
					.getConstructors()[0].newInstance(actors.robot, actors.world);
			State read = provider.currentState();
			// the provider reads a number for every argument; those the situation leaves unstated (the hospital's
			// distances between waypoints without a corridor) are the binding's 0 and are left out here
			State.Builder stated = read.toBuilder();
			for (var e : read.values().entrySet()) {
				if (expected.valueOf(e.getKey()).isEmpty() && !e.getKey().args().isEmpty() && e.getValue() instanceof Number n && n.doubleValue() == 0) {
					stated.retract(e.getKey());
				}
			}
			State observed = stated.build();
			assertEquals(expected, observed, () -> app[1] + ": observed " + observed);
			assertTrue(actors.executed.isEmpty());
		}
	}

	@Test
	void actionExecutorChecksPreconditionsAndCallsTheActorsMethods() throws Exception {
		State floor = situation(logistics, "Floor");
		StateBackedActors actors = new StateBackedActors(logistics, schemaOf(logistics), floor);
		ActionRunner executor = (ActionRunner) logistics.load("LogisticsDomainActionExecutor").getConstructors()[0]
				.newInstance(actors.robot, actors.world);
		DomainObject office = actors.object("office");
		DomainObject c1 = actors.object("c1");
		DomainObject c2 = actors.object("c2");

		assertEquals(Optional.empty(), executor.violatedPrecondition(new GroundAction("LogisticsRobot", "move", List.of(office, c1)), floor));
		assertEquals(Optional.of("LogisticsRobot.loc() == src"),
				executor.violatedPrecondition(new GroundAction("LogisticsRobot", "move", List.of(c1, c2)), floor));
		assertEquals(Optional.of("RoomsWorld.adj(src, dst)"),
				executor.violatedPrecondition(new GroundAction("LogisticsRobot", "move", List.of(office, c2)), floor));

		assertTrue(executor.execute(new GroundAction("LogisticsRobot", "move", List.of(office, c1))));
		assertEquals(List.of(new GroundAction("LogisticsRobot", "move", List.of(office, c1))), actors.executed);
		assertTrue(actors.executed.get(0).args().get(0).getClass().getName().endsWith(".domain.Room"));

		IllegalArgumentException notAWayPoint = assertThrows(IllegalArgumentException.class,
				() -> executor.execute(new GroundAction("LogisticsRobot", "move", List.of(office, "c1"))));
		assertTrue(notAWayPoint.getMessage().contains("argument 2 of LogisticsRobot.move(office, c1) is not a WayPoint"), notAWayPoint.getMessage());
		assertThrows(RuntimeException.class, () -> executor.execute(new GroundAction("LogisticsRobot", "fly", List.of(office))));
		assertEquals(1, actors.executed.size());
	}

	@Test
	void actionExecutorDispatchesWorldActionsToTheWorld() throws Exception {
		State morning = situation(hospital, "Morning");
		StateBackedActors actors = new StateBackedActors(hospital, schemaOf(hospital), morning);
		ActionRunner executor = (ActionRunner) hospital.load("HospitalActionExecutor").getConstructors()[0]
				.newInstance(actors.robot, actors.world);
		GroundAction walk = new GroundAction("Building", "walk", List.of(actors.object("alice"), actors.object("lobby"), actors.object("c4")));
		assertEquals(Optional.of("Building.walksAhead(p)"), executor.violatedPrecondition(walk, morning));
		assertTrue(executor.execute(walk));
		GroundAction pick = new GroundAction("Courier", "pick", List.of(actors.object("gauze"), actors.object("storage")));
		assertTrue(executor.execute(pick));
		assertEquals(List.of(walk, pick), actors.executed);
	}

	// ---- helpers -------------------------------------------------------------------------------

	private static TriadNames TriadNamesFor(GeneratedCode code) {
		return new TriadNames(code.loaded.application(), code.basePackage);
	}

	static AppSchema schemaOf(GeneratedCode code) throws Exception {
		return (AppSchema) code.load(TriadNamesFor(code).schemaClass()).getField("SCHEMA").get(null);
	}

	static State situation(GeneratedCode code, String name) {
		Situation s = code.loaded.application().getSituations().stream().filter(x -> x.getName().equals(name)).findFirst().orElseThrow();
		return SituationReader.read(s, SchemaBuilder.build(code.loaded.application()));
	}

	static DomainObject object(GeneratedCode code, String type, String name) throws Exception {
		return (DomainObject) code.load("domain." + type).getConstructor(String.class).newInstance(name);
	}

	static GoalInstance goal(GeneratedCode code, String name, Object... args) throws Exception {
		Object g = code.load("goals." + name).getConstructors()[0].newInstance(args);
		assertNotNull(g);
		return (GoalInstance) g;
	}
}
