package org.triad.dsl.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.triad.dsl.TriadTaskRuntimeModule;
import org.triad.dsl.TriadTaskStandaloneSetup;

/**
 * Sets the language up for the language server: its runtime and IDE modules, then the editor
 * services all Triad languages share ({@link TriadIdeBindings}).
 */
public class TriadTaskIdeSetup extends TriadTaskStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new TriadTaskRuntimeModule(), new TriadTaskIdeModule(), new TriadIdeBindings()));
	}
	
}
