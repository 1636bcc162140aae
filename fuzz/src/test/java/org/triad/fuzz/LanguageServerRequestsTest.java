package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentItem;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * The language server never answers with an internal error: every request of the protocol that
 * takes a document (whether the server advertises it or not) sent for each logistics model, a
 * broken model, a model past the expression depth limits and a document the server never saw, at
 * the start, inside every line, at the end and past the end, ends in a result or a proper LSP error
 * code, and nothing reaches the server's stderr or error log.
 */
class LanguageServerRequestsTest {
	private static LanguageServerSession session;
	private static final Map<String, String> documents = new LinkedHashMap<>();

	@BeforeAll
	static void openDocuments() throws Exception {
		session = new LanguageServerSession();
		for (String f : ModelCheckBoundary.BASE) {
			open(session.workspace.resolve(f), Files.readString(session.workspace.resolve(f)));
		}
		open(session.workspace.resolve("Broken.goal"), "domain LogisticsDomain;\n\ngoal Broken(WayPoint wp {\n  LogisticsRobot.loc( == && wp\n");
		open(session.workspace.resolve("Deep.goal"), "domain LogisticsDomain;\n\ngoal Deep(WayPoint wp) {\n  " + "(".repeat(150)
				+ "LogisticsRobot.loc() == wp" + ")".repeat(150) + "\n}\n");
		// not yet: a 20,000-level document, where completion still overflows Xtext's content-assist parser on the
		// partial-parse path (logged, answered empty); see FUZZING.md, finding 9
		documents.put(LanguageServerSession.uri(session.workspace.resolve("Unopened.goal")), "");
		documents.put("file:///nowhere/Elsewhere.task", "");
		session.takeProblems(); // opening is not under test here
	}

	private static void open(Path file, String text) throws Exception {
		Files.writeString(file, text);
		String uri = LanguageServerSession.uri(file);
		String ext = file.getFileName().toString().replaceFirst(".*\\.", "");
		session.server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, ext, 1, text)));
		documents.put(uri, text);
	}

	@AfterAll
	static void stop() throws Exception {
		if (session != null) {
			session.close();
		}
	}

	@Test
	void everyAdvertisedRequestIsExercised() {
		List<String> sent = new ArrayList<>(EditorRequests.at(session, "file:///x.goal", new Position(0, 0), new Position(0, 0)).keySet());
		List<String> advertised = EditorRequests.advertised(session.initialized.getCapabilities());
		assertTrue(advertised.size() >= 8, "capabilities read: " + advertised);
		assertEquals(List.of(), advertised.stream().filter(m -> !sent.contains(m)).toList(), "advertised but not exercised");
	}

	@TestFactory
	Stream<DynamicTest> everyRequestEndsInAResultOrAProperError() {
		List<String> methods = new ArrayList<>(EditorRequests.at(session, "file:///x.goal", new Position(0, 0), new Position(0, 0)).keySet());
		return methods.stream().map(method -> DynamicTest.dynamicTest(method, () -> {
			List<String> problems = new ArrayList<>();
			for (Map.Entry<String, String> doc : documents.entrySet()) {
				for (Position at : positions(doc.getValue())) {
					Position to = new Position(at.getLine() + 1, 0);
					session.answer(method, EditorRequests.at(session, doc.getKey(), at, to).get(method).get());
					for (String p : session.takeProblems()) {
						problems.add(doc.getKey().replaceFirst(".*/", "") + " @" + at.getLine() + ":" + at.getCharacter() + ": " + p);
					}
				}
			}
			assertEquals("", String.join("\n", problems.stream().limit(5).toList()),
					problems.size() + " bad answers, the first 5 shown");
		}));
	}

	/** The start, the middle of every line, the end of the text, and places past the end. */
	static List<Position> positions(String text) {
		List<Position> result = new ArrayList<>();
		result.add(new Position(0, 0));
		String[] lines = text.split("\n", -1);
		for (int i = 0; i < lines.length; i++) {
			int nonBlank = lines[i].length() - lines[i].stripLeading().length();
			result.add(new Position(i, nonBlank + (lines[i].length() - nonBlank) / 2));
		}
		result.add(new Position(lines.length - 1, lines[lines.length - 1].length()));
		result.add(new Position(lines.length + 5, 3));
		result.add(new Position(0, 10_000));
		return result;
	}
}
