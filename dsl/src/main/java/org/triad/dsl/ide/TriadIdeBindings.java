package org.triad.dsl.ide;

import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.ide.editor.syntaxcoloring.ISemanticHighlightingCalculator;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.ide.server.signatureHelp.ISignatureHelpService;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper;
import org.eclipse.xtext.resource.IContainer;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsProvider;
import org.triad.dsl.ide.hover.ModelDocumentation;
import org.triad.dsl.ide.hover.TriadHoverService;
import org.triad.dsl.ide.quickfix.ModelQuickFixes;
import org.triad.dsl.ide.symbols.ModelSymbolDetails;
import org.triad.dsl.ide.symbols.ModelSymbolKinds;
import org.triad.dsl.ide.symbols.ModelSymbolNames;
import org.triad.dsl.ide.workspace.ApplicationContainerManager;
import org.triad.dsl.ide.workspace.ApplicationIndexProvider;

import com.google.inject.AbstractModule;

/**
 * The editor services every Triad language shares: hover, quick fixes, signature help, semantic
 * tokens, document symbols, a rename that refuses clashes, and one application per folder. Mixed in last by each language's IDE
 * setup, so these bindings win over Xtext's defaults.
 */
public final class TriadIdeBindings extends AbstractModule {
	@Override
	protected void configure() {
		bind(IEObjectDocumentationProvider.class).to(ModelDocumentation.class);
		bind(IHoverService.class).to(TriadHoverService.class);
		bind(ICodeActionService2.class).to(ModelQuickFixes.class);
		bind(ISignatureHelpService.class).to(ModelSignatureHelp.class);
		bind(ISemanticHighlightingCalculator.class).to(ModelSemanticTokens.class);
		bind(DocumentSymbolMapper.DocumentSymbolNameProvider.class).to(ModelSymbolNames.class);
		bind(DocumentSymbolMapper.DocumentSymbolKindProvider.class).to(ModelSymbolKinds.class);
		bind(DocumentSymbolMapper.DocumentSymbolDetailsProvider.class).to(ModelSymbolDetails.class);
		bind(IRenameService2.class).to(ModelRenameService.class);
		// an editor's workspace may hold several applications: each model sees its own
		bind(IContainer.Manager.class).to(ApplicationContainerManager.class);
		bind(ResourceDescriptionsProvider.class).to(ApplicationIndexProvider.class);
	}
}
