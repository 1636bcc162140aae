package org.triad.dsl.ide;

import org.eclipse.xtext.ide.editor.contentassist.antlr.IContentAssistParser;
import org.triad.dsl.ide.contentassist.TriadTaskDepthSafeContentAssistParser;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;


/** IDE bindings of the .task language. */
public class TriadTaskIdeModule extends AbstractTriadTaskIdeModule {
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return TriadContentProposalProvider.class;
	}

	@Override
	public Class<? extends IContentAssistParser> bindIContentAssistParser() {
		return TriadTaskDepthSafeContentAssistParser.class;
	}
}
