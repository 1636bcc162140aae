package org.triad.dsl;

import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.scoping.impl.AbstractDeclarativeScopeProvider;
import org.triad.dsl.linking.TriadLinkingDiagnosticMessageProvider;
import org.triad.dsl.linking.TriadSyntaxErrorMessageProvider;
import org.triad.dsl.scoping.DomainImportScopeProvider;

import com.google.inject.AbstractModule;
import com.google.inject.name.Names;

/**
 * The bindings every Triad model language shares: {@code domain D;} as an implicit import, and the
 * stable codes of unresolved names and syntax errors. Installed by each language's runtime module.
 */
public final class TriadSharedBindings extends AbstractModule {
	@Override
	protected void configure() {
		bind(IScopeProvider.class).annotatedWith(Names.named(AbstractDeclarativeScopeProvider.NAMED_DELEGATE))
				.to(DomainImportScopeProvider.class);
		bind(ILinkingDiagnosticMessageProvider.class).to(TriadLinkingDiagnosticMessageProvider.class);
		bind(ISyntaxErrorMessageProvider.class).to(TriadSyntaxErrorMessageProvider.class);
	}
}
