package org.triad.dsl.ide.server;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.ProgressParams;
import org.eclipse.lsp4j.WorkDoneProgressBegin;
import org.eclipse.lsp4j.WorkDoneProgressEnd;
import org.eclipse.lsp4j.WorkDoneProgressNotification;
import org.eclipse.lsp4j.WorkDoneProgressReport;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Tells the editor what the server's first check of the workspace is doing, so that it is never silent
 * while Xtext loads and checks every model (inside {@code initialize}): {@code $/progress} with the token
 * the client gave in {@code initialize} (LSP allows it there), else {@code window/logMessage}; a report
 * every {@value #REPORT_EVERY_S} s while it lasts; at the end the number of model files; once the
 * diagnostics are out (after {@code initialized}) their count, as a {@code window/showMessage} warning
 * when models have errors.
 */
final class BuildProgress {
	static final int REPORT_EVERY_S = 2;

	private final LanguageClient client;
	private final Either<String, Integer> token;
	private final AtomicInteger files = new AtomicInteger();
	private final AtomicInteger published = new AtomicInteger();
	private final AtomicInteger filesWithErrors = new AtomicInteger();
	private final AtomicInteger errors = new AtomicInteger();
	private ScheduledExecutorService ticker;

	BuildProgress(LanguageClient client, Either<String, Integer> token) {
		this.client = client;
		this.token = token;
	}

	synchronized void begin(String where) {
		String message = "checking the models below " + where;
		if (token != null) {
			WorkDoneProgressBegin begin = new WorkDoneProgressBegin();
			begin.setTitle("Triad");
			begin.setMessage(message);
			notify(begin);
		} else {
			client.logMessage(new MessageParams(MessageType.Info, "Triad: " + message));
		}
		long start = System.nanoTime();
		ticker = Executors.newSingleThreadScheduledExecutor(r -> {
			Thread t = new Thread(r, "triad-build-progress");
			t.setDaemon(true);
			return t;
		});
		ticker.scheduleAtFixedRate(() -> tick(message + " (" + TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - start) + " s)"),
				REPORT_EVERY_S, REPORT_EVERY_S, TimeUnit.SECONDS);
	}

	/** The first build ended with this many model files. */
	void built(int modelFiles) {
		files.set(modelFiles);
	}

	/** The first check is done (its diagnostics are published once the client says {@code initialized}). */
	synchronized void end() {
		if (ticker == null) {
			return;
		}
		ticker.shutdownNow();
		ticker = null;
		String summary = count(files.get(), "model file") + " checked";
		if (token != null) {
			WorkDoneProgressEnd end = new WorkDoneProgressEnd();
			end.setMessage(summary);
			notify(end);
		} else {
			client.logMessage(new MessageParams(MessageType.Info, "Triad: " + summary));
		}
	}

	/** The diagnostics of one model file of the first check, with this many errors. */
	void published(int fileErrors) {
		published.incrementAndGet();
		if (fileErrors > 0) {
			filesWithErrors.incrementAndGet();
			errors.addAndGet(fileErrors);
		}
	}

	/** After the first check's diagnostics: how many errors, shown when there are some. */
	void summarize() {
		if (errors.get() == 0) {
			client.logMessage(new MessageParams(MessageType.Info, "Triad: " + count(files.get(), "model file") + ", no errors"));
			return;
		}
		String summary = "Triad: " + count(errors.get(), "error") + " in " + filesWithErrors.get() + " of " + count(files.get(), "model file")
				+ " (see the problems list)";
		client.logMessage(new MessageParams(MessageType.Info, summary));
		client.showMessage(new MessageParams(MessageType.Warning, summary));
	}

	private synchronized void tick(String message) {
		if (ticker == null) {
			return;
		}
		if (token != null) {
			WorkDoneProgressReport report = new WorkDoneProgressReport();
			report.setMessage(message);
			notify(report);
		} else {
			client.logMessage(new MessageParams(MessageType.Info, "Triad: " + message));
		}
	}

	private static String count(int n, String noun) {
		return n + " " + noun + (n == 1 ? "" : "s");
	}

	private void notify(WorkDoneProgressNotification value) {
		client.notifyProgress(new ProgressParams(token, Either.forLeft(value)));
	}
}
