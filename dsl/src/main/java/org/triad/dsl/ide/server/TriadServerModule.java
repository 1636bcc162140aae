package org.triad.dsl.ide.server;

import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.ServerModule;

import com.google.inject.AbstractModule;
import com.google.inject.util.Modules;

/** Xtext's server bindings with Triad's language server in place of Xtext's. */
public final class TriadServerModule extends AbstractModule {
	@Override
	protected void configure() {
		install(Modules.override(new ServerModule()).with(binder -> binder.bind(LanguageServerImpl.class).to(TriadLanguageServer.class)));
	}
}
