package org.triad.fuzz;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Handler;
import java.util.logging.LogRecord;

import org.apache.log4j.AppenderSkeleton;
import org.apache.log4j.Level;
import org.apache.log4j.Logger;
import org.apache.log4j.spi.LoggingEvent;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.triad.dsl.ide.server.TriadServerModule;
import org.triad.dsl.ide.server.TriadServerLauncher;

import com.google.inject.Guice;

/**
 * Triad's language server (what {@code triad lsp} runs: {@link GuardedServerModule}, {@link TriadServerLauncher}) in this JVM, spoken to over piped streams
 * like an editor does, in a workspace holding the logistics example. It records what would reach an
 * editor's log or the server's stderr: errors logged by Xtext (log4j) or LSP4J (java.util.logging)
 * and anything printed to {@link System#err}.
 */
final class LanguageServerSession implements AutoCloseable {
	static final long TIMEOUT_S = 60;

	/** Error codes that are proper answers to a request the server cannot serve; everything but an internal error. */
	private static final List<Integer> PROPER = List.of(ResponseErrorCode.MethodNotFound.getValue(),
			ResponseErrorCode.InvalidParams.getValue(), ResponseErrorCode.RequestCancelled.getValue(),
			ResponseErrorCode.ContentModified.getValue(), ResponseErrorCode.RequestFailed.getValue(),
			ResponseErrorCode.InvalidRequest.getValue());

	final Path workspace;
	final LanguageServer server;
	final InitializeResult initialized;
	private final Future<Void> serverListening;
	private final Future<Void> clientListening;
	private final List<String> problems = new ArrayList<>();
	private final WholeMessages clientOut;
	private final ByteArrayOutputStream stderr = new ByteArrayOutputStream();
	private final PrintStream originalErr = System.err;
	private final ErrorAppender log4j = new ErrorAppender();
	private final ErrorHandler jul = new ErrorHandler();

	LanguageServerSession() throws Exception {
		workspace = Files.createTempDirectory("triad-lsp-fuzz-");
		for (String f : ModelCheckBoundary.BASE) {
			Files.copy(ModelCheckBoundary.LOGISTICS.resolve(f), workspace.resolve(f));
		}
		System.setErr(new PrintStream(new TeeStream(stderr, originalErr), true, StandardCharsets.UTF_8));
		Logger.getRootLogger().addAppender(log4j);
		java.util.logging.Logger.getLogger("").addHandler(jul);

		PipedInputStream serverIn = new PipedInputStream(1 << 20);
		clientOut = new WholeMessages(new PipedOutputStream(serverIn));
		PipedInputStream clientIn = new PipedInputStream(1 << 20);
		PipedOutputStream serverOut = new PipedOutputStream(clientIn);
		LanguageServerImpl impl = Guice.createInjector(new TriadServerModule()).getInstance(LanguageServerImpl.class);
		Launcher<LanguageClient> serverLauncher = TriadServerLauncher.createLauncher(impl, serverIn, serverOut, true, null);
		serverListening = serverLauncher.startListening();
		Launcher<LanguageServer> clientLauncher = LSPLauncher.createClientLauncher(new QuietClient(), clientIn, clientOut);
		clientListening = clientLauncher.startListening();
		server = clientLauncher.getRemoteProxy();

		InitializeParams init = new InitializeParams();
		init.setProcessId((int) ProcessHandle.current().pid());
		init.setRootUri(uri(workspace));
		init.setCapabilities(new ClientCapabilities());
		initialized = server.initialize(init).get(TIMEOUT_S, TimeUnit.SECONDS);
		server.initialized(new InitializedParams());
	}

	/**
	 * Sends {@code content} to the server as one message, framed by its length, whatever it is: what a
	 * broken or hostile client could send.
	 */
	void sendRaw(byte[] content) throws IOException {
		clientOut.write(("Content-Length: " + content.length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
		clientOut.write(content);
		clientOut.flush();
	}

	/**
	 * The client's stream to the server, passing on what one thread wrote at its flush, in one piece: LSP4J
	 * writes a message's header and content with two writes and then flushes, so a raw message sent meanwhile
	 * from another thread could otherwise land between them.
	 */
	private static final class WholeMessages extends java.io.OutputStream {
		private final java.io.OutputStream out;
		private final ThreadLocal<ByteArrayOutputStream> pending = ThreadLocal.withInitial(ByteArrayOutputStream::new);

		WholeMessages(java.io.OutputStream out) {
			this.out = out;
		}

		@Override
		public void write(int b) {
			pending.get().write(b);
		}

		@Override
		public void write(byte[] b, int off, int len) {
			pending.get().write(b, off, len);
		}

		@Override
		public void flush() throws IOException {
			ByteArrayOutputStream p = pending.get();
			synchronized (out) {
				p.writeTo(out);
				out.flush();
			}
			p.reset();
		}

		@Override
		public void close() throws IOException {
			flush();
			out.close();
		}
	}

	static String uri(Path p) {
		return p.toUri().toString().replaceFirst("^file:/(?!/)", "file:///");
	}

	/**
	 * Waits for one request's answer: a result (null included) is fine, so is an error with a proper
	 * code; an internal error, a timeout or a broken connection is recorded as a problem.
	 */
	Object answer(String request, CompletableFuture<?> pending) {
		try {
			return pending.get(TIMEOUT_S, TimeUnit.SECONDS);
		} catch (ExecutionException e) {
			if (e.getCause() instanceof ResponseErrorException r) {
				ResponseError error = r.getResponseError();
				if (!PROPER.contains(error.getCode())) {
					problems.add(request + " answered error " + error.getCode() + ": " + error.getMessage());
				}
			} else {
				problems.add(request + " failed: " + e.getCause());
			}
		} catch (TimeoutException e) {
			problems.add(request + " got no answer in " + TIMEOUT_S + " s");
			pending.cancel(true);
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			problems.add(request + " interrupted");
		}
		return null;
	}

	/** What went wrong since the last call: bad answers, logged errors, text on stderr; then forgets it. */
	synchronized List<String> takeProblems() {
		List<String> result = new ArrayList<>(problems);
		problems.clear();
		result.addAll(log4j.take());
		result.addAll(jul.take());
		synchronized (stderr) {
			String err = stderr.toString(StandardCharsets.UTF_8);
			// the fuzzer itself reports on stderr ("INFO: ..."); what the server must not print is a stack trace
			if (err.contains("\tat ") || err.contains("Exception") || err.contains("SEVERE") || err.contains("ERROR")) {
				result.add("stderr: " + err);
			}
			stderr.reset();
		}
		return result;
	}

	@Override
	public void close() throws Exception {
		try {
			server.shutdown().get(TIMEOUT_S, TimeUnit.SECONDS); // no 'exit': Xtext's server would end this JVM
		} finally {
			serverListening.cancel(true);
			clientListening.cancel(true);
			Logger.getRootLogger().removeAppender(log4j);
			java.util.logging.Logger.getLogger("").removeHandler(jul);
			System.setErr(originalErr);
		}
	}

	private static final class TeeStream extends java.io.OutputStream {
		private final ByteArrayOutputStream copy;
		private final PrintStream out;

		TeeStream(ByteArrayOutputStream copy, PrintStream out) {
			this.copy = copy;
			this.out = out;
		}

		@Override
		public void write(int b) {
			synchronized (copy) {
				copy.write(b);
			}
			out.write(b);
		}

		@Override
		public void write(byte[] b, int off, int len) {
			synchronized (copy) {
				copy.write(b, off, len);
			}
			out.write(b, off, len);
		}
	}

	private static final class ErrorAppender extends AppenderSkeleton {
		private final List<String> errors = new ArrayList<>();

		@Override
		protected synchronized void append(LoggingEvent event) {
			if (event.getLevel().isGreaterOrEqual(Level.ERROR)) {
				String[] trace = event.getThrowableStrRep();
				errors.add("logged: " + event.getRenderedMessage() + (trace == null ? "" : "\n" + String.join("\n", trace)));
			}
		}

		synchronized List<String> take() {
			List<String> r = new ArrayList<>(errors);
			errors.clear();
			return r;
		}

		@Override
		public void close() {
		}

		@Override
		public boolean requiresLayout() {
			return false;
		}
	}

	private static final class ErrorHandler extends Handler {
		private final List<String> errors = new ArrayList<>();

		@Override
		public synchronized void publish(LogRecord record) {
			if (record.getLevel().intValue() >= java.util.logging.Level.WARNING.intValue()) {
				errors.add("logged: " + record.getMessage() + (record.getThrown() == null ? "" : " " + record.getThrown()));
			}
		}

		synchronized List<String> take() {
			List<String> r = new ArrayList<>(errors);
			errors.clear();
			return r;
		}

		@Override
		public void flush() {
		}

		@Override
		public void close() {
		}
	}

	/** An editor that accepts whatever the server tells it. */
	private static final class QuietClient implements LanguageClient {
		@Override
		public void telemetryEvent(Object object) {
		}

		@Override
		public void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
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
}
