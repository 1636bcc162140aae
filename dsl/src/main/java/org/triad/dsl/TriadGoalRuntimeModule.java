package org.triad.dsl;

import org.eclipse.xtext.parser.IParser;
import org.triad.dsl.parser.TriadGoalDepthLimitedParser;

import com.google.inject.Binder;

/** Runtime bindings of the .goal language: the Triad-wide ones, in place of Xtext's default scoping delegate;
 * a parser that stops at the expression depth limits. */
public class TriadGoalRuntimeModule extends AbstractTriadGoalRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}

	@Override
	public Class<? extends IParser> bindIParser() {
		return TriadGoalDepthLimitedParser.class;
	}
}
