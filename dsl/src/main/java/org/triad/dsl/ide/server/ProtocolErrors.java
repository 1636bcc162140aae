package org.triad.dsl.ide.server;

import java.util.logging.Level;
import java.util.logging.Logger;

import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;

/**
 * How a failed request is answered. LSP4J answers every exception with "internal error" and logs
 * its stack trace; that is right for a bug, but not for a request the server refuses on purpose:
 * a {@link ResponseErrorException} that Xtext wrapped (e.g. "Refactoring cannot be performed"
 * inside an {@code ExecutionException}) keeps its own code, and a protocol method the server does
 * not implement (LSP4J's default methods throw {@link UnsupportedOperationException}) is
 * "method not found", as the protocol says.
 */
public final class ProtocolErrors {
	private static final Logger LOG = Logger.getLogger(ProtocolErrors.class.getName());

	private ProtocolErrors() {
	}

	public static ResponseError toResponseError(Throwable failure) {
		for (Throwable t = failure; t != null; t = t.getCause() == t ? null : t.getCause()) {
			if (t instanceof ResponseErrorException e) {
				ResponseError error = e.getResponseError();
				// Xtext refuses e.g. a rename where nothing can be renamed with "unknown error"; the protocol's code is "request failed"
				return error.getCode() == ResponseErrorCode.UnknownErrorCode.getValue()
						? new ResponseError(ResponseErrorCode.RequestFailed, error.getMessage(), error.getData())
						: error;
			}
			if (t instanceof UnsupportedOperationException) {
				return new ResponseError(ResponseErrorCode.MethodNotFound, "the Triad language server does not implement this request", null);
			}
		}
		LOG.log(Level.SEVERE, "Internal error: " + failure, failure);
		return new ResponseError(ResponseErrorCode.InternalError, "Internal error: " + failure, null);
	}
}
