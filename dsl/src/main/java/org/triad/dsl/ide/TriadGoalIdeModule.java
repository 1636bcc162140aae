package org.triad.dsl.ide;

import org.eclipse.xtext.ide.editor.contentassist.antlr.IContentAssistParser;
import org.triad.dsl.ide.contentassist.TriadGoalDepthSafeContentAssistParser;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;


/** IDE bindings of the .goal language. */
public class TriadGoalIdeModule extends AbstractTriadGoalIdeModule {
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return TriadContentProposalProvider.class;
	}

	@Override
	public Class<? extends IContentAssistParser> bindIContentAssistParser() {
		return TriadGoalDepthSafeContentAssistParser.class;
	}
}
