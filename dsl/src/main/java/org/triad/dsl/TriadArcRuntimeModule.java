package org.triad.dsl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.scoping.impl.AbstractDeclarativeScopeProvider;
import org.triad.dsl.conversion.ArcValueConverters;
import org.triad.dsl.linking.ArcLinkingDiagnosticMessageProvider;
import org.triad.dsl.linking.TriadSyntaxErrorMessageProvider;
import org.triad.dsl.scoping.ArcImportScopeProvider;

import com.google.inject.Binder;
import com.google.inject.name.Names;

/** Runtime bindings of the architecture language (.arc). */
public class TriadArcRuntimeModule extends AbstractTriadArcRuntimeModule {
	@Override
	public void configureIScopeProviderDelegate(Binder binder) {
		binder.bind(IScopeProvider.class).annotatedWith(Names.named(AbstractDeclarativeScopeProvider.NAMED_DELEGATE))
				.to(ArcImportScopeProvider.class);
	}

	public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
		return ArcLinkingDiagnosticMessageProvider.class;
	}

	public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
		return TriadSyntaxErrorMessageProvider.class;
	}

	@Override
	public Class<? extends IValueConverterService> bindIValueConverterService() {
		return ArcValueConverters.class;
	}
}
