package org.triad.dsl.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.triad.dsl.TriadActorRuntimeModule;
import org.triad.dsl.TriadActorStandaloneSetup;

/**
 * Sets the language up for the language server: its runtime and IDE modules, then the editor
 * services all Triad languages share ({@link TriadIdeBindings}).
 */
public class TriadActorIdeSetup extends TriadActorStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new TriadActorRuntimeModule(), new TriadActorIdeModule(), new TriadIdeBindings()));
	}
	
}
