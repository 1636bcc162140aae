package org.triad.dsl.ide.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.xtext.service.OperationCanceledManager;
import org.junit.jupiter.api.Test;

/**
 * The bound on one request: a read that never looks at its cancel indicator (as Xtext's formatter
 * does not) is answered with "request failed" naming the bound, and a change that comes after it
 * goes ahead instead of waiting for it to end.
 */
class GuardedRequestManagerTest {
	@Test
	void aReadPastTheBoundIsAnsweredWithAnErrorAndDoesNotHoldUpChanges() throws Exception {
		ExecutorService parallel = Executors.newCachedThreadPool();
		GuardedRequestManager requests = new GuardedRequestManager(parallel, new OperationCanceledManager(), Duration.ofSeconds(1),
				Duration.ofSeconds(1));
		CountDownLatch release = new CountDownLatch(1);
		try {
			CompletableFuture<String> stubborn = requests.runRead(cancel -> {
				try {
					release.await(); // ignores 'cancel', the way a long formatting does
				} catch (InterruptedException e) {
					Thread.currentThread().interrupt();
				}
				return "late";
			});
			ExecutionException failed = assertThrows(ExecutionException.class, () -> stubborn.get(60, TimeUnit.SECONDS));
			ResponseErrorException error = assertInstanceOf(ResponseErrorException.class, failed.getCause());
			assertEquals(ResponseErrorCode.RequestFailed.getValue(), error.getResponseError().getCode());
			assertTrue(error.getMessage().contains("longer than 1 s"), error.getMessage());

			CompletableFuture<String> change = requests.runWrite(() -> "changed", (cancel, value) -> value);
			assertEquals("changed", change.get(60, TimeUnit.SECONDS));
			assertFalse(release.getCount() == 0, "the change went ahead while the stubborn read still ran");

			CompletableFuture<String> next = requests.runRead(cancel -> "answered");
			assertEquals("answered", next.get(60, TimeUnit.SECONDS));
		} finally {
			release.countDown();
			requests.shutdown();
		}
	}
}
