package org.triad.dsl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.EcoreUtil2;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.app.ApplicationAssembler;
import org.triad.dsl.app.LoadedApplication;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.ClassDiagram;
import org.triad.dsl.triad.DomainTypeRef;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.PropertyCall;

/** Names resolve across the files of an application, as LANGUAGES.md says. */
class CrossFileLinkingTest {

	private static LoadedApplication load(Path dir, String... nameAndText) throws IOException {
		for (int i = 0; i < nameAndText.length; i += 2) {
			Files.writeString(dir.resolve(nameAndText[i]), nameAndText[i + 1]);
		}
		return ApplicationAssembler.load(dir);
	}

	private static String printed(LoadedApplication app) {
		return app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n"));
	}

	static final String DOMAIN = """
			classdiagram Shop {
			  class Place;
			  class Room extends Place;
			}
			""";
	static final String ROBOT = """
			domain Shop;
			robot Bot {
			  property Place loc();
			  action move(Place a, Place b) {
			    pre: loc() == a && World.adj(a, b);
			    post: loc() == b;
			  }
			}
			""";
	static final String WORLD = """
			domain Shop;
			world World {
			  property boolean adj(Place a, Place b);
			  property Place loc();
			  action shift(Place p) {
			    post: loc() == p;
			  }
			}
			""";
	static final String GOAL = """
			domain Shop;
			goal At(Room r) {
			  Bot.loc() == r
			}
			""";

	@Test
	void goalReferencesAnActorPropertyOfAnotherFile(@TempDir Path dir) throws IOException {
		LoadedApplication app = load(dir, "Shop.cd", DOMAIN, "Bot.actor", ROBOT, "World.actor", WORLD, "At.goal", GOAL);
		assertEquals("", printed(app));
		Goal goal = app.application().getGoals().get(0);
		PropertyCall call = EcoreUtil2.getAllContentsOfType(goal, PropertyCall.class).get(0);
		assertFalse(call.getProperty().eIsProxy());
		assertEquals("Bot.actor", call.getProperty().eResource().getURI().lastSegment());
		assertSame(app.application().getRobot(), call.getActor());
		assertSame(app.application().getRobot().getProperties().get(0), call.getProperty());
	}

	@Test
	void unqualifiedCallsInsideAnActorMeanItsOwnProperties(@TempDir Path dir) throws IOException {
		// both actors have a property loc(); each action's unqualified loc() is its own actor's
		LoadedApplication app = load(dir, "Shop.cd", DOMAIN, "Bot.actor", ROBOT, "World.actor", WORLD, "At.goal", GOAL);
		assertEquals("", printed(app));
		Actor bot = app.application().getRobot();
		Actor world = app.application().getWorld();
		for (Actor actor : List.of(bot, world)) {
			for (Action action : actor.getActions()) {
				for (PropertyCall call : EcoreUtil2.getAllContentsOfType(action, PropertyCall.class)) {
					if (call.getActor() == null) {
						assertSame(actor, call.getProperty().eContainer(), action.getName() + ": " + call.getProperty().getName());
					}
				}
			}
		}
		PropertyCall qualified = EcoreUtil2.getAllContentsOfType(bot.getActions().get(0), PropertyCall.class).stream()
				.filter(c -> c.getActor() != null).findFirst().orElseThrow();
		assertSame(world, qualified.getProperty().eContainer());
	}

	@Test
	void domainDeclarationExposesThatDiagramsTypesBySimpleName(@TempDir Path dir) throws IOException {
		// two class diagrams both define Place: 'domain X;' decides which one a simple name means
		String other = """
				classdiagram Depot {
				  class Place;
				}
				""";
		String goals = """
				domain Depot;
				goal Somewhere(Place p) {
				  Bot.loc() == p
				}
				""";
		LoadedApplication app = load(dir, "Shop.cd", DOMAIN, "Depot.cd", other, "Bot.actor", ROBOT, "World.actor", WORLD, "At.goal",
				GOAL, "Somewhere.goal", goals);
		ClassDiagram shop = (ClassDiagram) app.resourceSet().getResources().stream()
				.filter(r -> r.getURI().lastSegment().equals("Shop.cd")).findFirst().orElseThrow().getContents().get(0);
		ClassDiagram depot = (ClassDiagram) app.resourceSet().getResources().stream()
				.filter(r -> r.getURI().lastSegment().equals("Depot.cd")).findFirst().orElseThrow().getContents().get(0);
		Property loc = app.application().getRobot().getProperties().get(0);
		assertSame(shop.getTypes().get(0), ((DomainTypeRef) loc.getType()).getType());
		Goal somewhere = app.application().getGoals().stream().filter(g -> g.getName().equals("Somewhere")).findFirst().orElseThrow();
		assertSame(depot.getTypes().get(0), ((DomainTypeRef) somewhere.getParameters().get(0).getType()).getType());
		// Depot's Place is no Shop Place: comparing them is a type error; two diagrams are a structure error
		assertEquals("""
				Shop.cd:1:14: error app.class-diagram-count: the application has more than one class diagram: 'Shop' and 'Depot'
				Somewhere.goal:3:13: error expr.incompatible-operands: cannot compare Shop.Place with Depot.Place using '=='""", printed(app));
	}

	@Test
	void typesOfAnotherDiagramAreNotVisibleBySimpleName(@TempDir Path dir) throws IOException {
		String goals = """
				domain Depot;
				goal Somewhere(Room r) {
				  Bot.loc() == r
				}
				""";
		LoadedApplication app = load(dir, "Shop.cd", DOMAIN, "Depot.cd", "classdiagram Depot { class Place; }\n", "Bot.actor", ROBOT,
				"World.actor", WORLD, "Somewhere.goal", goals);
		assertEquals("""
				Shop.cd:1:14: error app.class-diagram-count: the application has more than one class diagram: 'Shop' and 'Depot'
				Somewhere.goal:2:16: error link.unknown-type: unknown type 'Room'""", printed(app));
	}
}
