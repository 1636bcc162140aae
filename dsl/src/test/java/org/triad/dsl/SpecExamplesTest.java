package org.triad.dsl;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;

/**
 * The examples of the language contract (LANGUAGES.md), copied verbatim, form an application
 * that loads without a diagnostic. Only the world actor and the goal IsAt, which the contract
 * refers to without showing them, are added.
 */
class SpecExamplesTest {

	@Test
	void contractExamplesLoadCleanly(@TempDir Path dir) throws IOException {
		Files.writeString(dir.resolve("Hospital.cd"), """
				classdiagram Hospital {
				  class WayPoint;                       // body optional
				  class Room extends WayPoint { String name; }
				  abstract class Thing { String label; int weight; }
				  class Item extends Thing;
				  enum DoorState { OPEN, CLOSED; }
				}
				""");
		Files.writeString(dir.resolve("Courier.actor"), """
				domain Hospital;
				robot Courier {
				  property WayPoint loc();
				  property boolean carries(Item i);
				  property boolean handEmpty();
				  action move(WayPoint src, WayPoint dst) {
				    pre: loc() == src && Building.adj(src, dst);
				    post: loc() == dst;
				  }
				}
				""");
		Files.writeString(dir.resolve("Holds.goal"), """
				domain Hospital;
				goal Holds(Item i) { Courier.carries(i) }
				""");
		Files.writeString(dir.resolve("Fetch.task"), """
				domain Hospital;
				task Fetch(Item i, Room from, Room to) {
				  IsAt(from);
				  Holds(i);
				  IsAt(to);
				}
				""");
		Files.writeString(dir.resolve("Morning.state"), """
				domain Hospital;
				state Morning {
				  Room storage, ward3;          // objects, by type
				  Item gauze { label = "gauze"; weight = 1; };   // attribute values optional
				  Courier.loc() == storage;     // facts in the expression language
				  Courier.handEmpty();
				  Building.adj(storage, ward3);
				}
				""");
		// not shown in the contract, referred to by the examples
		Files.writeString(dir.resolve("Building.actor"), """
				domain Hospital;
				world Building {
				  property boolean adj(WayPoint a, WayPoint b);
				  property DoorState door(WayPoint a, WayPoint b);
				  action open(WayPoint a, WayPoint b) {
				    pre: door(a, b) == DoorState.CLOSED;
				    post: door(a, b) == DoorState.OPEN;
				  }
				}
				""");
		Files.writeString(dir.resolve("IsAt.goal"), """
				domain Hospital;
				goal IsAt(WayPoint w) { Courier.loc() == w }
				""");
		LoadedApplication app = ApplicationAssembler.load(dir);
		assertEquals("", app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n")));
	}

	@Test
	void expressionPrecedenceIsAsSpecified(@TempDir Path dir) throws IOException {
		// weakest first: ||, &&, !, comparison; '!a == b' negates the comparison, so it is boolean
		Files.writeString(dir.resolve("Hospital.cd"), "classdiagram Hospital { class WayPoint; }\n");
		Files.writeString(dir.resolve("Courier.actor"), """
				domain Hospital;
				robot Courier {
				  property WayPoint loc();
				  property boolean busy();
				  property int load();
				  action a(WayPoint w) {
				    pre: !loc() == w || busy() && load() < 3 && 2.5 >= load() && "x" != "y";
				  }
				}
				""");
		Files.writeString(dir.resolve("Building.actor"), "domain Hospital;\nworld Building {\n}\n");
		LoadedApplication app = ApplicationAssembler.load(dir);
		assertEquals("", app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n")));
	}
}
