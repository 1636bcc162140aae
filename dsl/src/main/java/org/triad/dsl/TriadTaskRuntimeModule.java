package org.triad.dsl;

import com.google.inject.Binder;

/** Runtime bindings of the .task language: the Triad-wide ones, in place of Xtext's default scoping delegate. */
public class TriadTaskRuntimeModule extends AbstractTriadTaskRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}
}
