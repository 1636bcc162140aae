package org.triad.dsl.ide.server;

import org.eclipse.xtext.ide.server.LanguageServerImpl;

import com.google.inject.AbstractModule;
import com.google.inject.util.Modules;

/** Xtext's server bindings with Triad's language server in place of Xtext's. */
public final class TriadServerModule extends AbstractModule {
	@Override
	protected void configure() {
		install(Modules.override(new GuardedServerModule()).with(binder -> binder.bind(LanguageServerImpl.class).to(TriadLanguageServer.class)));
	}
}
