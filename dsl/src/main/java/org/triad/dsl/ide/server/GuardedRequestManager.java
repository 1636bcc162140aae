package org.triad.dsl.ide.server;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.ide.server.concurrent.RequestManager;
import org.eclipse.xtext.service.OperationCanceledManager;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.xbase.lib.Exceptions;
import org.eclipse.xtext.xbase.lib.Functions.Function1;

import com.google.inject.Inject;

/**
 * Xtext's request manager with two guards.
 * <p>
 * A read request (every request an editor sends but {@code initialize}: hover, completion, formatting,
 * ...) is answered within {@link #REQUEST_BOUND}: past it, the request is cancelled and answered with
 * "request failed" naming the bound. And a change to the documents waits at most {@link #WRITE_WAIT}
 * for the reads it cancelled: Xtext's own manager waits until they end, so a read that does not look at
 * its cancel indicator (Xtext's formatter does not) held up every later change, and so every later
 * request, for as long as it ran. The read that went on is left to end on its own; its result and any
 * failure it meets after its cancellation are dropped.
 * <p>
 * And it lets a read request refuse with a {@link ResponseErrorException} (an unknown document, an
 * unknown command) without Xtext logging it as "Error during request" with a stack trace: the refusal
 * travels past Xtext's request as a value and becomes the request's error outside it.
 */
public class GuardedRequestManager extends RequestManager {
	/** How long a read request may take: far above what any request on a model takes, far below an editor's patience. */
	public static final Duration REQUEST_BOUND = Duration.ofSeconds(Long.getLong("triad.lsp.requestSeconds", 60));
	/**
	 * How long a change waits for the reads it cancelled before it goes ahead: long enough that a read that
	 * honours its cancel indicator has stopped (even on a loaded machine) before the change touches the
	 * models it reads, short enough that one that does not cannot hold up every later request for minutes.
	 */
	public static final Duration WRITE_WAIT = Duration.ofSeconds(20);

	private static final ScheduledExecutorService DEADLINES = Executors.newSingleThreadScheduledExecutor(r -> {
		Thread t = new Thread(r, "triad-lsp-request-deadlines");
		t.setDaemon(true);
		return t;
	});

	private record Refusal(ResponseErrorException error) {
	}

	private final Duration bound;
	private final Duration writeWait;

	private static ResponseErrorException refusalIn(Throwable failure) {
		for (Throwable t = failure; t != null; t = t.getCause() == t ? null : t.getCause()) {
			if (t instanceof ResponseErrorException e) {
				return e;
			}
		}
		return null;
	}

	@Inject
	public GuardedRequestManager(ExecutorService parallel, OperationCanceledManager operationCanceledManager) {
		this(parallel, operationCanceledManager, REQUEST_BOUND, WRITE_WAIT);
	}

	GuardedRequestManager(ExecutorService parallel, OperationCanceledManager operationCanceledManager, Duration bound, Duration writeWait) {
		super(parallel, operationCanceledManager);
		this.bound = bound;
		this.writeWait = writeWait;
	}

	@Override
	@SuppressWarnings("unchecked")
	public synchronized <V> CompletableFuture<V> runRead(Function1<? super CancelIndicator, ? extends V> cancellable) {
		CompletableFuture<Object> inner = super.runRead(cancel -> {
			try {
				return cancellable.apply(cancel);
			} catch (Exception e) { // Xtext's rename wraps its refusal in an ExecutionException, thrown past the compiler
				if (cancel.isCanceled()) {
					// cancelled (by the client, a change, or the bound): whatever it met since is no error of its own
					getOperationCanceledManager().throwOperationCanceledException();
				}
				ResponseErrorException refusal = refusalIn(e);
				if (refusal == null) {
					throw Exceptions.sneakyThrow(e);
				}
				return new Refusal(refusal);
			}
		});
		CompletableFuture<V> outer = new CompletableFuture<>() {
			@Override
			public boolean cancel(boolean mayInterruptIfRunning) {
				inner.cancel(mayInterruptIfRunning);
				return super.cancel(mayInterruptIfRunning);
			}
		};
		inner.whenComplete((result, failure) -> {
			if (failure != null) {
				outer.completeExceptionally(failure);
			} else if (result instanceof Refusal refusal) {
				outer.completeExceptionally(refusal.error());
			} else {
				outer.complete((V) result);
			}
		});
		ScheduledFuture<?> deadline = DEADLINES.schedule(() -> {
			// answered first, so that the answer is the bound and not the cancellation it causes
			if (outer.completeExceptionally(new ResponseErrorException(new ResponseError(ResponseErrorCode.RequestFailed,
					"the request took longer than " + bound.toSeconds() + " s, the Triad language server's bound for one request, and was stopped",
					null)))) {
				inner.cancel(true);
			}
		}, bound.toMillis(), TimeUnit.MILLISECONDS);
		outer.whenComplete((result, failure) -> deadline.cancel(false));
		return outer;
	}

	/** The reads a change cancels, waited for {@link #WRITE_WAIT} at most. */
	@Override
	protected CompletableFuture<Void> cancel() {
		return super.cancel().completeOnTimeout(null, writeWait.toMillis(), TimeUnit.MILLISECONDS);
	}
}
