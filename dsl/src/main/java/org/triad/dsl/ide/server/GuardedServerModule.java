package org.triad.dsl.ide.server;

import org.eclipse.xtext.ide.server.ServerLauncher;
import org.eclipse.xtext.ide.server.ServerModule;
import org.eclipse.xtext.ide.server.WorkspaceManager;
import org.eclipse.xtext.ide.server.commands.ExecutableCommandRegistry;
import org.eclipse.xtext.ide.server.concurrent.RequestManager;

import com.google.inject.AbstractModule;
import com.google.inject.util.Modules;

/**
 * Xtext's server bindings with the guards that make every request end in a result or a proper LSP
 * error: unknown documents and out-of-range positions ({@link GuardedWorkspaceManager}), unknown
 * commands ({@link GuardedCommandRegistry}), refusals that are not logged as errors
 * ({@link GuardedRequestManager}), and the launcher's answer to failures ({@link TriadServerLauncher}).
 */
public final class GuardedServerModule extends AbstractModule {
	@Override
	protected void configure() {
		install(Modules.override(new ServerModule()).with(binder -> {
			binder.bind(WorkspaceManager.class).to(GuardedWorkspaceManager.class);
			binder.bind(ExecutableCommandRegistry.class).to(GuardedCommandRegistry.class);
			binder.bind(ServerLauncher.class).to(TriadServerLauncher.class);
			binder.bind(RequestManager.class).to(GuardedRequestManager.class);
		}));
	}
}
