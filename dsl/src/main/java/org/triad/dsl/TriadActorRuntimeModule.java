package org.triad.dsl;

import org.eclipse.xtext.parser.IParser;
import org.triad.dsl.parser.TriadActorDepthLimitedParser;

import com.google.inject.Binder;

/** Runtime bindings of the .actor language: the Triad-wide ones, in place of Xtext's default scoping delegate;
 * a parser that stops at the expression depth limits. */
public class TriadActorRuntimeModule extends AbstractTriadActorRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}

	@Override
	public Class<? extends IParser> bindIParser() {
		return TriadActorDepthLimitedParser.class;
	}
}
