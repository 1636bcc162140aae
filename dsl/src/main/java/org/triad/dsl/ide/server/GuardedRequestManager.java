package org.triad.dsl.ide.server;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;

import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.xtext.ide.server.concurrent.RequestManager;
import org.eclipse.xtext.service.OperationCanceledManager;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.xbase.lib.Exceptions;
import org.eclipse.xtext.xbase.lib.Functions.Function1;

import com.google.inject.Inject;

/**
 * Xtext's request manager, letting a read request refuse with a {@link ResponseErrorException}
 * (an unknown document, an unknown command) without Xtext logging it as "Error during request"
 * with a stack trace: the refusal travels past Xtext's request as a value and becomes the
 * request's error outside it.
 */
public class GuardedRequestManager extends RequestManager {
	private record Refusal(ResponseErrorException error) {
	}

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
		super(parallel, operationCanceledManager);
	}

	@Override
	@SuppressWarnings("unchecked")
	public synchronized <V> CompletableFuture<V> runRead(Function1<? super CancelIndicator, ? extends V> cancellable) {
		CompletableFuture<Object> inner = super.runRead(cancel -> {
			try {
				return cancellable.apply(cancel);
			} catch (Exception e) { // Xtext's rename wraps its refusal in an ExecutionException, thrown past the compiler
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
		return outer;
	}
}
