package org.triad.dsl;

import com.google.inject.Binder;

/** Runtime bindings of the .cd language: the Triad-wide ones, in place of Xtext's default scoping delegate. */
public class TriadCdRuntimeModule extends AbstractTriadCdRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}
}
