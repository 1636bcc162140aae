package org.triad.dsl;

import com.google.inject.Binder;

/** Runtime bindings of the .goal language: the Triad-wide ones, in place of Xtext's default scoping delegate. */
public class TriadGoalRuntimeModule extends AbstractTriadGoalRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}
}
