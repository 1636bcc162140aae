package org.triad.dsl;

import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.triad.dsl.linking.TriadLinkingDiagnosticMessageProvider;
import org.triad.dsl.linking.TriadSyntaxErrorMessageProvider;
import org.triad.dsl.scoping.DomainImportScopeProvider;

import com.google.inject.Binder;
import com.google.inject.name.Names;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.scoping.impl.AbstractDeclarativeScopeProvider;

/** Runtime bindings of the .cd language; the Triad-wide ones are the same in every language module. */
public class TriadCdRuntimeModule extends AbstractTriadCdRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.bind(IScopeProvider.class).annotatedWith(Names.named(AbstractDeclarativeScopeProvider.NAMED_DELEGATE))
				.to(DomainImportScopeProvider.class);
	}

	public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
		return TriadLinkingDiagnosticMessageProvider.class;
	}

	public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
		return TriadSyntaxErrorMessageProvider.class;
	}
}
