package org.triad.dsl;

import org.eclipse.xtext.parser.IParser;
import org.triad.dsl.parser.TriadTaskDepthLimitedParser;

import com.google.inject.Binder;

/** Runtime bindings of the .task language: the Triad-wide ones, in place of Xtext's default scoping delegate;
 * a parser that stops at the expression depth limits. */
public class TriadTaskRuntimeModule extends AbstractTriadTaskRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.install(new TriadSharedBindings());
	}

	@Override
	public Class<? extends IParser> bindIParser() {
		return TriadTaskDepthLimitedParser.class;
	}
}
