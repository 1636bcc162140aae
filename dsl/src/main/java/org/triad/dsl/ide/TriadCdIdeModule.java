package org.triad.dsl.ide;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;


/** IDE bindings of the .cd language. */
public class TriadCdIdeModule extends AbstractTriadCdIdeModule {
	public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
		return TriadContentProposalProvider.class;
	}
}
