package org.triad.dsl.ide;

import org.eclipse.xtext.ide.editor.contentassist.antlr.IContentAssistParser;
import org.triad.dsl.ide.contentassist.TriadActorDepthSafeContentAssistParser;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;


/** IDE bindings of the .actor language. */
public class TriadActorIdeModule extends AbstractTriadActorIdeModule {
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return TriadContentProposalProvider.class;
	}

	@Override
	public Class<? extends IContentAssistParser> bindIContentAssistParser() {
		return TriadActorDepthSafeContentAssistParser.class;
	}
}
