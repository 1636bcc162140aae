package org.triad.dsl.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.triad.dsl.TriadCommonRuntimeModule;
import org.triad.dsl.TriadCommonStandaloneSetup;

/**
 * Sets the language up for the language server: its runtime and IDE modules, then the editor
 * services all Triad languages share ({@link TriadIdeBindings}).
 */
public class TriadCommonIdeSetup extends TriadCommonStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new TriadCommonRuntimeModule(), new TriadCommonIdeModule(), new TriadIdeBindings()));
	}
	
}
