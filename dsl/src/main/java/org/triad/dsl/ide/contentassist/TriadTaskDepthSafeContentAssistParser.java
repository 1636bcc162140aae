package org.triad.dsl.ide.contentassist;

import java.util.Set;

import org.eclipse.xtext.ide.editor.contentassist.antlr.FollowElement;
import org.eclipse.xtext.ide.editor.contentassist.antlr.internal.AbstractInternalContentAssistParser;
import org.triad.dsl.ide.contentassist.antlr.TriadTaskParser;

/** The .task content-assist parser, which proposes nothing in a text nested past {@link ContentAssistDepth}. */
public class TriadTaskDepthSafeContentAssistParser extends TriadTaskParser {
	@Override
	protected Set<FollowElement> getFollowElements(AbstractInternalContentAssistParser parser, String ruleName, boolean strict) throws Exception {
		return ContentAssistDepth.tooDeep(parser.getTokenStream()) ? Set.of() : super.getFollowElements(parser, ruleName, strict);
	}
}
