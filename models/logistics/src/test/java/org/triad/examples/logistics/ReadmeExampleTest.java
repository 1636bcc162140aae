package org.triad.examples.logistics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.triad.generator.Situations;
import org.triad.refarc.RefArcRun;
import org.triad.refarc.Status;
import org.triad.refarc.TaskRunner;
import org.triad.runtime.app.Atom;
import org.triad.runtime.app.State;

import generated.logisticsdomain.LogisticsDomainRefArc;
import generated.logisticsdomain.LogisticsDomainSchema;
import generated.logisticsdomain.domain.Room;
import generated.logisticsdomain.domain.WayPoint;

/** The README's "Running tasks from Java" example, line for line, and what it promises. */
class ReadmeExampleTest {

	@Test
	void readmeExample() {
		List<Status> seen = new ArrayList<>();
		// --- README example begins
		FloorPlan world = new FloorPlan();                                       // the application's IWorld
		Room office = world.room("office", "Office"), lab = world.room("lab", "Lab");
		WayPoint c1 = world.wayPoint("c1");
		world.connect(office, c1).connect(c1, office).connect(c1, lab);
		RefArcRun run = LogisticsDomainRefArc.of(new LogisticsRobot(world, office), world)
				.onStatus(seen::add)                                             // each Status as it happens
				.run("GoTo", "office", "lab");                                   // a task by name, objects by name
		// run.outcome() == COMPLETED; run.statuses(): every Status

		State floor = Situations.load(Path.of("src/main/models"), LogisticsDomainSchema.class).state("Floor");
		Room library = (Room) floor.object("library").orElseThrow();           // the generated class, attributes set
		RefArcRun dry = TaskRunner.dry(LogisticsDomainSchema.SCHEMA, floor).run("GoTo", "office", library);
		// --- README example ends

		assertEquals(RefArcRun.Outcome.COMPLETED, run.outcome(), run.log().toString());
		assertEquals(run.statuses(), seen, "the observer saw every Status, in order");
		assertInstanceOf(Status.TaskCompleted.class, seen.get(seen.size() - 1));
		assertEquals("Library", library.getName());
		assertEquals(RefArcRun.Outcome.COMPLETED, dry.outcome(), dry.log().toString());
		assertTrue(dry.log().stream().anyMatch(l -> l.contains("move(c3, library)")), dry.log().toString());
	}

	@Test
	void aSituationThatExtendsAnotherHasItsObjectsAndFactsWithItsOwnOverriding() {
		Situations situations = Situations.load(Path.of("src/main/models"), LogisticsDomainSchema.class);
		State floor = situations.state("Floor");
		State inLab = situations.state("InLab");
		assertEquals(floor.objects().keySet(), inLab.objects().keySet());
		assertEquals(Optional.of(floor.object("office").orElseThrow()), floor.valueOf(Atom.of("LogisticsRobot", "loc")));
		assertEquals(Optional.of(inLab.object("lab").orElseThrow()), inLab.valueOf(Atom.of("LogisticsRobot", "loc")));
		assertEquals(floor.values().size(), inLab.values().size(), "the same adjacency, one value overridden");
		assertInstanceOf(Room.class, inLab.valueOf(Atom.of("LogisticsRobot", "loc")).orElseThrow(), "values are generated objects too");
		assertEquals(floor, situations.state("Floor.state"), "a file's first situation");
	}

	@Test
	void wrongTaskCallsAreRefusedWithTheReason() {
		State floor = Situations.load(Path.of("src/main/models"), LogisticsDomainSchema.class).state("Floor");
		TaskRunner dry = TaskRunner.dry(LogisticsDomainSchema.SCHEMA, floor);
		assertEquals("application LogisticsDomain has no task 'Goto'; its tasks: [GoTo]",
				assertThrows(IllegalArgumentException.class, () -> dry.run("Goto", "office", "lab")).getMessage());
		assertTrue(assertThrows(IllegalArgumentException.class, () -> dry.run("GoTo", "office", "kitchen")).getMessage()
				.contains("no object 'kitchen'"));
		assertTrue(assertThrows(IllegalArgumentException.class, () -> dry.run("GoTo", "office", "c1")).getMessage()
				.contains("parameter dst takes a Room, not WayPoint 'c1'"));
		assertTrue(assertThrows(IllegalArgumentException.class, () -> dry.run("GoTo", "office")).getMessage()
				.contains("takes 2 argument(s), not 1"));
		assertTrue(assertThrows(IllegalArgumentException.class, () -> Situations.load(Path.of("src/main/models"), LogisticsDomainSchema.class)
				.state("Evening")).getMessage().contains("[Floor, InLab]"));
	}
}
