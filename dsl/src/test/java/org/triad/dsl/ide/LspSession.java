package org.triad.dsl.ide;

import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.triad.dsl.ide.server.TriadServerModule;

import com.google.inject.Guice;

/**
 * Triad's language server driven over the protocol through piped streams, as an editor drives it:
 * started on a workspace folder with the given client capabilities, recording what the server
 * sends unasked (diagnostics, capability registrations).
 */
final class LspSession implements AutoCloseable {
	static final long TIMEOUT_S = 60;

	final Path workspace;
	final LanguageServer server;
	final InitializeResult initializeResult;
	final Client client = new Client();
	private final Future<Void> serverListening;
	private final Future<Void> clientListening;

	/** Collects what the server sends unasked. */
	static final class Client implements LanguageClient {
		final Map<String, List<Diagnostic>> diagnostics = new ConcurrentHashMap<>();
		final List<RegistrationParams> registrations = new CopyOnWriteArrayList<>();

		@Override
		public synchronized void publishDiagnostics(PublishDiagnosticsParams params) {
			diagnostics.put(params.getUri(), params.getDiagnostics());
			notifyAll();
		}

		@Override
		public CompletableFuture<Void> registerCapability(RegistrationParams params) {
			registrations.add(params);
			synchronized (this) {
				notifyAll();
			}
			return CompletableFuture.completedFuture(null);
		}

		/** Waits until the diagnostics of {@code uri} satisfy {@code condition}; returns them either way. */
		synchronized List<Diagnostic> await(String uri, Predicate<List<Diagnostic>> condition) throws InterruptedException {
			long end = System.currentTimeMillis() + TIMEOUT_S * 1000;
			while (!condition.test(diagnostics.getOrDefault(uri, List.of())) && System.currentTimeMillis() < end) {
				wait(200);
			}
			return diagnostics.getOrDefault(uri, List.of());
		}

		synchronized List<Diagnostic> awaitCode(String uri, String code) throws InterruptedException {
			return await(uri, ds -> ds.stream().anyMatch(d -> d.getCode() != null && code.equals(d.getCode().getLeft())));
		}

		/** Waits until diagnostics of {@code uri} were published at all (possibly none); returns them. */
		synchronized List<Diagnostic> awaitPublished(String uri) throws InterruptedException {
			long end = System.currentTimeMillis() + TIMEOUT_S * 1000;
			while (!diagnostics.containsKey(uri) && System.currentTimeMillis() < end) {
				wait(200);
			}
			return diagnostics.getOrDefault(uri, List.of());
		}

		synchronized void awaitRegistration() throws InterruptedException {
			long end = System.currentTimeMillis() + TIMEOUT_S * 1000;
			while (registrations.isEmpty() && System.currentTimeMillis() < end) {
				wait(200);
			}
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

	LspSession(Path workspace, ClientCapabilities capabilities) throws Exception {
		this.workspace = workspace;
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
		init.setRootUri(uri(workspace));
		init.setCapabilities(capabilities);
		initializeResult = server.initialize(init).get(TIMEOUT_S, TimeUnit.SECONDS);
		server.initialized(new InitializedParams());
	}

	@Override
	public void close() throws Exception {
		// no 'exit': Xtext's server ends the JVM on it, which would end the test run
		server.shutdown().get(TIMEOUT_S, TimeUnit.SECONDS);
		serverListening.cancel(true);
		clientListening.cancel(true);
	}

	/** The file URI the way the server writes it (file:///path). */
	static String uri(Path p) {
		return p.toUri().toString().replaceFirst("^file:/(?!/)", "file:///");
	}

	String uri(String fileName) {
		return uri(workspace.resolve(fileName));
	}

	/** Opens a workspace file in the editor with its text on disk. */
	String open(String fileName) throws IOException {
		return open(fileName, Files.readString(workspace.resolve(fileName)));
	}

	/** Opens a file in the editor with the given text (written to disk first if the file is new). */
	String open(String fileName, String text) throws IOException {
		Path file = workspace.resolve(fileName);
		if (!Files.exists(file)) {
			Files.writeString(file, text);
		}
		String uri = uri(file);
		String languageId = fileName.substring(fileName.lastIndexOf('.') + 1);
		server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, languageId, 1, text)));
		return uri;
	}

	/** The position {@code delta} characters into the first occurrence of {@code marker} in {@code text}. */
	static Position at(String text, String marker, int delta) {
		int offset = text.indexOf(marker);
		if (offset < 0) {
			throw new IllegalArgumentException("'" + marker + "' not in the text");
		}
		offset += delta;
		int line = 0;
		int lineStart = 0;
		for (int i = 0; i < offset; i++) {
			if (text.charAt(i) == '\n') {
				line++;
				lineStart = i + 1;
			}
		}
		return new Position(line, offset - lineStart);
	}

	static <T> T get(CompletableFuture<T> f) throws Exception {
		return f.get(TIMEOUT_S, TimeUnit.SECONDS);
	}
}
