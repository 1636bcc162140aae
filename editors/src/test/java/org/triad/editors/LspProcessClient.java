package org.triad.editors;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Future;

import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;

/** An LSP client talking to a language server process over its standard input and output. */
final class LspProcessClient implements LanguageClient, AutoCloseable {
	private final Map<String, List<Diagnostic>> diagnostics = new ConcurrentHashMap<>();
	private final Map<String, Integer> publications = new ConcurrentHashMap<>();
	private final LanguageServer server;
	private final Future<Void> listening;

	LspProcessClient(Process process) {
		Launcher<LanguageServer> launcher = LSPLauncher.createClientLauncher(this, process.getInputStream(), process.getOutputStream());
		listening = launcher.startListening();
		server = launcher.getRemoteProxy();
	}

	LanguageServer server() {
		return server;
	}

	/** Waits (at most a minute) for diagnostics of a file whose URI ends with {@code fileName}; the first one's code. */
	synchronized String awaitFirstCode(String fileName) throws InterruptedException {
		long end = System.currentTimeMillis() + 60_000;
		while (System.currentTimeMillis() < end) {
			for (Map.Entry<String, List<Diagnostic>> e : diagnostics.entrySet()) {
				if (e.getKey().endsWith("/" + fileName) && !e.getValue().isEmpty()) {
					return e.getValue().get(0).getCode().getLeft();
				}
			}
			wait(200);
		}
		return null;
	}

	/** How many times diagnostics of {@code uri} were published so far. */
	int publications(String uri) {
		return publications.getOrDefault(uri, 0);
	}

	/** Waits (at most a minute) until diagnostics of {@code uri} are published more than {@code seen} times. */
	synchronized void awaitPublication(String uri, int seen) throws InterruptedException {
		long end = System.currentTimeMillis() + 60_000;
		while (publications(uri) <= seen) {
			long left = end - System.currentTimeMillis();
			if (left <= 0) {
				throw new IllegalStateException("no diagnostics for " + uri + " within a minute");
			}
			wait(Math.min(left, 50));
		}
	}

	/** Error diagnostics currently published, over all files, as "uri: code message". */
	List<String> errors() {
		return diagnostics.entrySet().stream().flatMap(e -> e.getValue().stream()
				.filter(d -> d.getSeverity() == org.eclipse.lsp4j.DiagnosticSeverity.Error)
				.map(d -> e.getKey() + ": " + d.getCode().getLeft() + " " + d.getMessage().getLeft())).toList();
	}

	@Override
	public synchronized void publishDiagnostics(PublishDiagnosticsParams params) {
		diagnostics.put(params.getUri(), params.getDiagnostics());
		publications.merge(params.getUri(), 1, Integer::sum);
		notifyAll();
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

	@Override
	public void close() {
		listening.cancel(true);
	}
}
