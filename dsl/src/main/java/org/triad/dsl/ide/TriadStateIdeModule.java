package org.triad.dsl.ide;

import org.eclipse.xtext.ide.editor.contentassist.antlr.IContentAssistParser;
import org.triad.dsl.ide.contentassist.TriadStateDepthSafeContentAssistParser;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;


/** IDE bindings of the .state language. */
public class TriadStateIdeModule extends AbstractTriadStateIdeModule {
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return TriadContentProposalProvider.class;
	}

	@Override
	public Class<? extends IContentAssistParser> bindIContentAssistParser() {
		return TriadStateDepthSafeContentAssistParser.class;
	}
}
