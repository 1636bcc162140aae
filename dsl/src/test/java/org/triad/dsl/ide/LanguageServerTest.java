package org.triad.dsl.ide;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.triad.dsl.ide.server.TriadServerModule;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.google.inject.Guice;

/**
 * The language server (the one {@code triad lsp} runs), driven over the protocol through piped
 * streams like an editor: diagnostics with code and range, completion, go-to-definition across
 * files, and formatting.
 */
class LanguageServerTest {
	private static final long TIMEOUT_S = 60;

	@TempDir
	static Path workspace;

	private static final RecordingClient client = new RecordingClient();
	private static LanguageServer server;
	private static Future<Void> serverListening;
	private static Future<Void> clientListening;

	/** Collects what the server sends unasked. */
	static final class RecordingClient implements LanguageClient {
		final Map<String, List<Diagnostic>> diagnostics = new ConcurrentHashMap<>();

		@Override
		public void publishDiagnostics(PublishDiagnosticsParams params) {
			synchronized (this) {
				diagnostics.put(params.getUri(), params.getDiagnostics());
				notifyAll();
			}
		}

		/** Waits until the diagnostics of {@code uri} contain one with {@code code}. */
		synchronized List<Diagnostic> awaitDiagnostic(String uri, String code) throws InterruptedException {
			long end = System.currentTimeMillis() + TIMEOUT_S * 1000;
			while (!has(uri, code) && System.currentTimeMillis() < end) {
				wait(500);
			}
			return diagnostics.getOrDefault(uri, List.of());
		}

		private boolean has(String uri, String code) {
			return diagnostics.getOrDefault(uri, List.of()).stream().anyMatch(d -> d.getCode() != null && code.equals(d.getCode().getLeft()));
		}

		@Override
		public void telemetryEvent(Object object) {
		}

		@Override
		public void showMessage(MessageParams messageParams) {
		}

		@Override
		public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams requestParams) {
			return CompletableFuture.completedFuture(null);
		}

		@Override
		public void logMessage(MessageParams message) {
		}
	}

	@BeforeAll
	static void startServerOnPipes() throws Exception {
		Path base = Path.of("src", "test", "resources", "rules", "_base");
		try (Stream<Path> files = Files.list(base)) {
			for (Path f : files.toList()) {
				Files.copy(f, workspace.resolve(f.getFileName()));
			}
		}
		PipedInputStream serverIn = new PipedInputStream(1 << 16);
		PipedOutputStream clientOut = new PipedOutputStream(serverIn);
		PipedInputStream clientIn = new PipedInputStream(1 << 16);
		PipedOutputStream serverOut = new PipedOutputStream(clientIn);

		LanguageServerImpl impl = Guice.createInjector(new TriadServerModule()).getInstance(LanguageServerImpl.class);
		Launcher<LanguageClient> serverLauncher = LSPLauncher.createServerLauncher(impl, serverIn, serverOut);
		impl.connect(serverLauncher.getRemoteProxy());
		serverListening = serverLauncher.startListening();

		Launcher<LanguageServer> clientLauncher = LSPLauncher.createClientLauncher(client, clientIn, clientOut);
		clientListening = clientLauncher.startListening();
		server = clientLauncher.getRemoteProxy();

		InitializeParams init = new InitializeParams();
		init.setProcessId((int) ProcessHandle.current().pid());
		init.setRootUri(uri(workspace)); // Xtext reads the root URI unless the client announces workspace folders
		init.setCapabilities(new ClientCapabilities());
		InitializeResult result = server.initialize(init).get(TIMEOUT_S, TimeUnit.SECONDS);
		assertTrue(result.getCapabilities().getDefinitionProvider().isLeft() || result.getCapabilities().getDefinitionProvider().isRight());
		server.initialized(new InitializedParams());
	}

	@AfterAll
	static void stopServer() throws Exception {
		// no 'exit': Xtext's server ends the JVM on it, which would end the test run
		server.shutdown().get(TIMEOUT_S, TimeUnit.SECONDS);
		serverListening.cancel(true);
		clientListening.cancel(true);
	}

	private static String uri(Path p) {
		// the server normalises file URIs to file:///path
		return p.toUri().toString().replaceFirst("^file:/(?!/)", "file:///");
	}

	private static String open(String fileName, String text) throws IOException {
		Path file = workspace.resolve(fileName);
		if (!Files.exists(file)) {
			Files.writeString(file, text);
		}
		String uri = uri(file);
		String languageId = fileName.substring(fileName.lastIndexOf('.') + 1);
		server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, languageId, 1, text)));
		return uri;
	}

	@Test
	void publishesDiagnosticWithCodeAndRangeForAnOpenedModel() throws Exception {
		String uri = open("Broken.goal", """
				domain Shop;

				goal Broken(Place p) {
				  Bot.loc() == p && Bot.location() == p
				}
				""");
		List<Diagnostic> diagnostics = client.awaitDiagnostic(uri, "link.unknown-property");
		assertEquals(1, diagnostics.size(), diagnostics.toString());
		Diagnostic d = diagnostics.get(0);
		assertEquals("link.unknown-property", d.getCode().getLeft());
		assertEquals(DiagnosticSeverity.Error, d.getSeverity());
		// 0-based: line 4 of the file, 'location' fromcolumn 25 (1-based) on
		assertEquals(new Range(new Position(3, 24), new Position(3, 32)), d.getRange());
		assertTrue(d.getMessage().getLeft().contains("location"), d.getMessage().getLeft());
	}

	@Test
	void completesThePropertiesOfAnActor() throws Exception {
		String text = """
				domain Shop;

				goal Near(Place p) {
				  World.
				}
				""";
		String uri = open("Near.goal", text);
		CompletionParams params = new CompletionParams(new TextDocumentIdentifier(uri), new Position(3, 8));
		Either<List<CompletionItem>, CompletionList> result = server.getTextDocumentService().completion(params).get(TIMEOUT_S,
				TimeUnit.SECONDS);
		List<CompletionItem> items = result.isLeft() ? result.getLeft() : result.getRight().getItems();
		List<String> labels = items.stream().map(CompletionItem::getLabel).sorted().collect(Collectors.toList());
		// World's properties, not the robot's, nor qualified names of everything
		assertEquals(List.of("adj", "boxAt", "door"), labels);
	}

	@Test
	void completionAnswersThroughoutHalfTypedModels() throws Exception {
		// every other position of half-typed models, where completion runs on broken text
		for (String name : List.of("Bot.actor", "Start.state", "Go.task")) {
			String text = Files.readString(workspace.resolve(name));
			for (String variant : List.of(text.substring(0, text.length() / 2), text.replace(")", ""))) {
				String uri = uri(workspace.resolve("Typing" + name));
				server.getTextDocumentService().didOpen(
						new DidOpenTextDocumentParams(new TextDocumentItem(uri, name.substring(name.indexOf('.') + 1), 1, variant)));
				List<String> lines = variant.lines().toList();
				for (int line = 0; line < lines.size(); line++) {
					for (int character = line % 2; character <= lines.get(line).length(); character += 2) {
						CompletionParams params = new CompletionParams(new TextDocumentIdentifier(uri), new Position(line, character));
						// an exception in the server comes back as an error response, and get() throws it
						server.getTextDocumentService().completion(params).get(TIMEOUT_S, TimeUnit.SECONDS);
					}
				}
				server.getTextDocumentService().didClose(new org.eclipse.lsp4j.DidCloseTextDocumentParams(new TextDocumentIdentifier(uri)));
			}
		}
	}

	@Test
	void goesToTheDefinitionOfAPropertyInAnotherFile() throws Exception {
		String uri = uri(workspace.resolve("At.goal"));
		String text = Files.readString(workspace.resolve("At.goal"));
		server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "goal", 1, text)));
		// At.goal line 4 is "  Bot.loc() == p": the cursor on 'loc'
		DefinitionParams params = new DefinitionParams(new TextDocumentIdentifier(uri), new Position(3, 8));
		Either<List<? extends Location>, List<? extends LocationLink>> result = server.getTextDocumentService().definition(params)
				.get(TIMEOUT_S, TimeUnit.SECONDS);
		List<? extends Location> locations = result.getLeft();
		assertEquals(1, locations.size(), locations.toString());
		Location target = locations.get(0);
		assertEquals(uri(workspace.resolve("Bot.actor")), target.getUri());
		// Bot.actor line 4 is "  property Place loc();": the name 'loc'
		assertEquals(new Range(new Position(3, 17), new Position(3, 20)), target.getRange());
	}

	@Test
	void formatsADocument() throws Exception {
		String text = "domain Shop;\ngoal  Far(Place p){Bot.loc()!=p&&!Bot.handEmpty()}\n";
		String uri = open("Far.goal", text);
		List<? extends TextEdit> edits = server.getTextDocumentService()
				.formatting(new DocumentFormattingParams(new TextDocumentIdentifier(uri), new FormattingOptions(2, true)))
				.get(TIMEOUT_S, TimeUnit.SECONDS);
		assertEquals("domain Shop;\n\ngoal Far(Place p) {\n  Bot.loc() != p && !Bot.handEmpty()\n}\n", apply(text, edits));
	}

	@Test
	void formattingAnEmptyDocumentChangesNothing() throws Exception {
		String uri = open("Empty.task", "");
		List<? extends TextEdit> edits = server.getTextDocumentService()
				.formatting(new DocumentFormattingParams(new TextDocumentIdentifier(uri), new FormattingOptions(2, true)))
				.get(TIMEOUT_S, TimeUnit.SECONDS);
		assertEquals(List.of(), edits);
	}

	/** Applies LSP edits (non-overlapping) to a text. */
	private static String apply(String text, List<? extends TextEdit> edits) {
		List<TextEdit> sorted = new java.util.ArrayList<>(edits);
		sorted.sort((a, b) -> Integer.compare(offset(text, b.getRange().getStart()), offset(text, a.getRange().getStart())));
		StringBuilder result = new StringBuilder(text);
		for (TextEdit edit : sorted) {
			result.replace(offset(text, edit.getRange().getStart()), offset(text, edit.getRange().getEnd()), edit.getNewText());
		}
		return result.toString();
	}

	private static int offset(String text, Position position) {
		int offset = 0;
		for (int line = 0; line < position.getLine(); line++) {
			offset = text.indexOf('\n', offset) + 1;
		}
		return offset + position.getCharacter();
	}
}
