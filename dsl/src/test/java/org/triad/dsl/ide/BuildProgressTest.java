package org.triad.dsl.ide;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.ProgressParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.WorkDoneProgressBegin;
import org.eclipse.lsp4j.WorkDoneProgressEnd;
import org.eclipse.lsp4j.WorkDoneProgressNotification;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.triad.dsl.ide.server.TriadServerModule;

import com.google.inject.Guice;

/**
 * The server's first check of the workspace is not silent: with the client's work-done token it sends
 * {@code $/progress} begin and end (the counts), without one {@code window/logMessage}; errors at start
 * also get a {@code window/showMessage}.
 */
class BuildProgressTest {
	@TempDir
	Path workspace;

	static final class Client implements LanguageClient {
		final List<WorkDoneProgressNotification> progress = new CopyOnWriteArrayList<>();
		final List<MessageParams> logged = new CopyOnWriteArrayList<>();
		final List<MessageParams> shown = new CopyOnWriteArrayList<>();

		@Override
		public void notifyProgress(ProgressParams params) {
			assertEquals("init-1", params.getToken().getLeft());
			progress.add(params.getValue().getLeft());
		}

		@Override
		public void publishDiagnostics(PublishDiagnosticsParams params) {
		}

		@Override
		public void telemetryEvent(Object object) {
		}

		@Override
		public void showMessage(MessageParams params) {
			shown.add(params);
		}

		@Override
		public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams params) {
			return CompletableFuture.completedFuture(null);
		}

		@Override
		public void logMessage(MessageParams params) {
			logged.add(params);
		}
	}

	@Test
	void theFirstCheckReportsProgressAndItsErrors() throws Exception {
		copyBase();
		Files.writeString(workspace.resolve("Broken.goal"), "domain Shop;\n\ngoal Broken(Place p) {\n  Bot.location() == p\n}\n");
		Client client = initialize(Either.forLeft("init-1"));
		assertTrue(client.progress.get(0) instanceof WorkDoneProgressBegin b && b.getMessage().startsWith("checking the models below "),
				client.progress.toString());
		WorkDoneProgressNotification last = client.progress.get(client.progress.size() - 1);
		assertTrue(last instanceof WorkDoneProgressEnd, client.progress.toString());
		assertEquals("7 model files checked", ((WorkDoneProgressEnd) last).getMessage());
		assertEquals(1, client.shown.size(), client.shown.toString());
		assertEquals(MessageType.Warning, client.shown.get(0).getType());
		assertEquals("Triad: 1 error in 1 of 7 model files (see the problems list)", client.shown.get(0).getMessage());
	}

	@Test
	void withoutAWorkDoneTokenTheCheckIsLogged() throws Exception {
		copyBase();
		Client client = initialize(null);
		assertEquals(List.of(), client.progress);
		assertTrue(client.logged.get(0).getMessage().startsWith("Triad: checking the models below "), client.logged.toString());
		assertTrue(client.logged.stream().anyMatch(m -> m.getMessage().equals("Triad: 6 model files checked")), client.logged.toString());
		assertEquals("Triad: 6 model files, no errors", client.logged.get(client.logged.size() - 1).getMessage());
		assertEquals(List.of(), client.shown, "no errors, nothing shown");
	}

	private void copyBase() throws Exception {
		try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", "rules", "_base"))) {
			for (Path f : files.toList()) {
				Files.copy(f, workspace.resolve(f.getFileName()));
			}
		}
	}

	private Client initialize(Either<String, Integer> token) throws Exception {
		PipedInputStream serverIn = new PipedInputStream(1 << 16);
		PipedOutputStream clientOut = new PipedOutputStream(serverIn);
		PipedInputStream clientIn = new PipedInputStream(1 << 16);
		PipedOutputStream serverOut = new PipedOutputStream(clientIn);
		LanguageServerImpl impl = Guice.createInjector(new TriadServerModule()).getInstance(LanguageServerImpl.class);
		Launcher<LanguageClient> serverLauncher = LSPLauncher.createServerLauncher(impl, serverIn, serverOut);
		impl.connect(serverLauncher.getRemoteProxy());
		Future<Void> serverListening = serverLauncher.startListening();
		Client client = new Client();
		Launcher<LanguageServer> clientLauncher = LSPLauncher.createClientLauncher(client, clientIn, clientOut);
		Future<Void> clientListening = clientLauncher.startListening();
		LanguageServer server = clientLauncher.getRemoteProxy();
		try {
			InitializeParams init = new InitializeParams();
			init.setProcessId((int) ProcessHandle.current().pid());
			init.setRootUri(workspace.toUri().toString());
			init.setCapabilities(new ClientCapabilities());
			init.setWorkDoneToken(token);
			server.initialize(init).get(60, TimeUnit.SECONDS);
			server.initialized(new org.eclipse.lsp4j.InitializedParams());
			// notifications sent before the response are delivered in order; a shutdown round trip flushes the rest
			server.shutdown().get(60, TimeUnit.SECONDS);
			return client;
		} finally {
			serverListening.cancel(true);
			clientListening.cancel(true);
		}
	}
}
