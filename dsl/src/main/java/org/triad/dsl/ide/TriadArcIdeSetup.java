package org.triad.dsl.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.triad.dsl.TriadArcRuntimeModule;
import org.triad.dsl.TriadArcStandaloneSetup;

/**
 * Sets the language up for the language server: its runtime and IDE modules, then the editor
 * services all Triad languages share ({@link TriadIdeBindings}).
 */
public class TriadArcIdeSetup extends TriadArcStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new TriadArcRuntimeModule(), new TriadArcIdeModule(), new TriadIdeBindings()));
	}
	
}
