package org.triad.dsl.ide.server;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.xtext.ide.server.ILanguageServerAccess;
import org.eclipse.xtext.ide.server.commands.ExecutableCommandRegistry;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.util.CancelIndicator;

/**
 * Xtext's command registry, refusing a command it does not offer with "invalid params"; Xtext's
 * fails with a null pointer when the client did not announce commands at start.
 */
public class GuardedCommandRegistry extends ExecutableCommandRegistry {
	private volatile boolean initialized;

	@Override
	public void initialize(Iterable<? extends IResourceServiceProvider> allLanguages, ClientCapabilities capabilities, LanguageClient client) {
		super.initialize(allLanguages, capabilities, client);
		initialized = true;
	}

	@Override
	public Object executeCommand(ExecuteCommandParams params, ILanguageServerAccess access, CancelIndicator cancelIndicator) {
		if (!initialized || !getCommands().contains(params.getCommand())) {
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.InvalidParams,
					"unknown command '" + params.getCommand() + "'; the server offers " + (initialized ? getCommands() : "none"), null));
		}
		return super.executeCommand(params, access, cancelIndicator);
	}
}
