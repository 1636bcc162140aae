package org.triad.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;

import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceSymbolParams;
import org.junit.jupiter.api.AfterAll;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * The language server's document handling: an editor buffer of one of the model languages (chosen
 * by the input's first byte) changes to arbitrary text; the server re-reads it and answers the
 * requests an editor sends while typing (completion, hover, definition, highlights, symbols,
 * folding, formatting, semantic tokens) with results or proper errors, and logs nothing as an error.
 * Seeds: the example models, each behind its language's byte
 * ({@code src/test/resources/org/triad/fuzz/LanguageServerFuzzTestInputs/editedDocument/}).
 */
class LanguageServerFuzzTest {
	static final List<String> LANGUAGES = List.of("cd", "actor", "goal", "task", "state", "arc");
	private static final List<String> WHILE_TYPING = List.of("textDocument/completion", "textDocument/hover",
			"textDocument/definition", "textDocument/documentHighlight", "textDocument/documentSymbol",
			"textDocument/foldingRange", "textDocument/formatting", "textDocument/semanticTokens/full");

	private static LanguageServerSession session;
	private static final int[] versions = new int[LANGUAGES.size()];

	@FuzzTest(maxDuration = "10m")
	void editedDocument(byte[] input) throws Exception {
		if (input.length == 0) {
			return;
		}
		LanguageServerSession s = session();
		int language = Byte.toUnsignedInt(input[0]) % LANGUAGES.size();
		String text = new String(Arrays.copyOfRange(input, 1, input.length), StandardCharsets.UTF_8);
		String uri = LanguageServerSession.uri(s.workspace.resolve("Edited." + LANGUAGES.get(language)));
		int version = ++versions[language];
		if (version == 1) {
			s.server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, LANGUAGES.get(language), 1, text)));
		} else {
			s.server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(new VersionedTextDocumentIdentifier(uri, version),
					List.of(new TextDocumentContentChangeEvent(text))));
		}
		List<String> problems = new ArrayList<>();
		for (Position at : places(text)) {
			Map<String, Supplier<CompletableFuture<?>>> requests = EditorRequests.at(s, uri, at, new Position(at.getLine() + 1, 0));
			for (String method : WHILE_TYPING) {
				s.answer(method, requests.get(method).get());
			}
			problems.addAll(s.takeProblems());
		}
		assertEquals(List.of(), problems);
	}

	/**
	 * The server's reading of messages ({@code GuardedMessageProducer}): the input, whatever it is, arrives
	 * as the content of one message (framed by its length); the server answers it or refuses it, logs no
	 * error, and answers the next request: the stream stays in step. Inputs naming {@code exit},
	 * {@code shutdown} or {@code initialize} are skipped, since they end or restart this in-JVM server.
	 * Seeds: {@code LanguageServerFuzzTestInputs/rawMessage/}.
	 */
	@FuzzTest(maxDuration = "10m")
	void rawMessage(byte[] input) throws Exception {
		String text = new String(input, StandardCharsets.ISO_8859_1);
		if (text.contains("exit") || text.contains("shutdown") || text.contains("initialize")) {
			return;
		}
		LanguageServerSession s = session();
		s.sendRaw(input);
		s.answer("workspace/symbol after the raw message", s.server.getWorkspaceService().symbol(new WorkspaceSymbolParams("")));
		// the answer to a raw request reaches this test's LSP4J client, which sent no such request and logs it as
		// unmatched: that is the answer arriving, a problem only when it is an internal error
		List<String> problems = s.takeProblems().stream().filter(p -> !isAnswerToRawRequest(p)).toList();
		assertEquals(List.of(), problems);
	}

	/** The client's log line (or its copy on stderr) for an answer to the raw request, unless an internal error. */
	private static boolean isAnswerToRawRequest(String problem) {
		boolean unmatched = problem.startsWith("logged: Unmatched response message")
				|| problem.startsWith("stderr: ") && problem.contains("Unmatched response message") && !problem.contains("\tat ");
		return unmatched && !problem.contains("-32603");
	}

	/** Where the cursor is: the start, the middle of the text, its end. */
	private static List<Position> places(String text) {
		String[] lines = text.split("\n", -1);
		int mid = lines.length / 2;
		return List.of(new Position(0, 0), new Position(mid, lines[mid].length() / 2),
				new Position(lines.length - 1, lines[lines.length - 1].length()));
	}

	private static synchronized LanguageServerSession session() throws Exception {
		if (session == null) {
			session = new LanguageServerSession();
			session.takeProblems();
		}
		return session;
	}

	@AfterAll
	static void stop() throws Exception {
		if (session != null) {
			session.close();
			session = null;
		}
	}
}
