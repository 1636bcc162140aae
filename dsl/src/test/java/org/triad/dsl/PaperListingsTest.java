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
 * The paper's Listings 1-3 (the logistics example), copied verbatim without the line numbers:
 * they are the logistics application's models, and they load with no diagnostic.
 */
class PaperListingsTest {
	static final String LISTING_1 = """
			domain LogisticsDomain;

			robot LogisticsRobot {
			  property WayPoint loc();
			  action move(WayPoint src, WayPoint dst) {
			    pre: loc() == src && RoomsWorld.adj(src, dst);
			    post: loc() == dst;
			  }
			}
			""";
	static final String LISTING_2 = """
			domain LogisticsDomain;

			task GoTo(Room src, Room dst) {
			  IsAt(src);
			  IsAt(dst);
			}
			""";
	static final String LISTING_3 = """
			domain LogisticsDomain;

			goal IsAt(WayPoint wp) {
			  LogisticsRobot.loc() == wp
			}
			""";

	static final Path LOGISTICS = Path.of("..", "models", "logistics", "src", "main", "models");

	@Test
	void listingsAreTheLogisticsModels() throws IOException {
		assertEquals(LISTING_1, Files.readString(LOGISTICS.resolve("LogisticsRobot.actor")));
		assertEquals(LISTING_2, Files.readString(LOGISTICS.resolve("GoTo.task")));
		assertEquals(LISTING_3, Files.readString(LOGISTICS.resolve("IsAt.goal")));
	}

	@Test
	void listingsAloneWithTheirDomainAndWorldLoadCleanly(@TempDir Path dir) throws IOException {
		Files.writeString(dir.resolve("LogisticsRobot.actor"), LISTING_1);
		Files.writeString(dir.resolve("GoTo.task"), LISTING_2);
		Files.writeString(dir.resolve("IsAt.goal"), LISTING_3);
		// the paper shows the domain and the world only as a figure (Fig. 2); these are the shipped ones
		Files.copy(LOGISTICS.resolve("LogisticsDomain.cd"), dir.resolve("LogisticsDomain.cd"));
		Files.copy(LOGISTICS.resolve("RoomsWorld.actor"), dir.resolve("RoomsWorld.actor"));
		LoadedApplication app = ApplicationAssembler.load(dir);
		assertEquals("", app.diagnostics().stream().map(d -> d.format(app.root())).collect(Collectors.joining("\n")));
		assertEquals("LogisticsRobot", app.application().getRobot().getName());
		assertEquals(1, app.application().getTasks().size());
		assertEquals(2, app.application().getTasks().get(0).getSteps().size());
		assertEquals("IsAt", app.application().getTasks().get(0).getSteps().get(1).getGoal().getName());
	}
}
