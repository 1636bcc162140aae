package org.triad.generator.arc;

import org.eclipse.xtext.generator.IGenerator2;
import org.triad.dsl.TriadArcRuntimeModule;
import org.triad.dsl.TriadArcStandaloneSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;

/** The architecture language with its Java generator bound, for {@code xtext-maven-plugin}'s {@code <setup>}. */
public class ArcJavaGeneratorSetup extends TriadArcStandaloneSetup {
	@Override
	public Injector createInjector() {
		return Guice.createInjector(new Module());
	}

	/** The architecture language's runtime module plus the generator. */
	public static class Module extends TriadArcRuntimeModule {
		public Class<? extends IGenerator2> bindIGenerator2() {
			return ArcGenerator.class;
		}
	}
}
