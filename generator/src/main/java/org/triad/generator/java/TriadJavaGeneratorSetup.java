package org.triad.generator.java;

import org.eclipse.xtext.generator.IGenerator2;
import org.triad.dsl.TriadCdRuntimeModule;
import org.triad.dsl.TriadCdStandaloneSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;

/**
 * The class-diagram language with the Java generator bound, for {@code xtext-maven-plugin}'s
 * {@code <setup>}; list the other Triad languages with their own setups so their models link.
 */
public class TriadJavaGeneratorSetup extends TriadCdStandaloneSetup {
	@Override
	public Injector createInjector() {
		return Guice.createInjector(new Module());
	}

	/** The class-diagram runtime module plus the generator. */
	public static class Module extends TriadCdRuntimeModule {
		public Class<? extends IGenerator2> bindIGenerator2() {
			return TriadApplicationGenerator.class;
		}
	}
}
