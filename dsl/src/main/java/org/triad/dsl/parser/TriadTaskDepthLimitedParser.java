package org.triad.dsl.parser;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Action;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.parser.antlr.XtextTokenStream;
import org.triad.dsl.parser.antlr.TriadTaskParser;
import org.triad.dsl.parser.antlr.internal.InternalTriadTaskParser;

/** The .task parser, kept inside the {@link ExpressionLimits} by an {@link ExpressionDepthGuard}. */
public class TriadTaskDepthLimitedParser extends TriadTaskParser {
	@Override
	protected InternalTriadTaskParser createParser(XtextTokenStream stream) {
		ExpressionDepthGuard guard = new ExpressionDepthGuard(stream);
		return new InternalTriadTaskParser(stream, getGrammarAccess()) {
			@Override
			protected void newCompositeNode(EObject grammarElement) {
				guard.enteringRule(grammarElement);
				super.newCompositeNode(grammarElement);
			}

			@Override
			protected void afterParserOrEnumRuleCall() {
				guard.leftRule();
				super.afterParserOrEnumRuleCall();
			}

			@Override
			protected EObject forceCreateModelElementAndSet(Action action, EObject value) {
				guard.stacking(value);
				EObject result = super.forceCreateModelElementAndSet(action, value);
				guard.attached(result, value);
				return result;
			}

			@Override
			protected void set(EObject parent, String feature, Object value, String lexerRule, INode node) {
				super.set(parent, feature, value, lexerRule, node);
				guard.attached(parent, value);
			}

			@Override
			protected void add(EObject parent, String feature, Object value, String lexerRule, INode node) {
				super.add(parent, feature, value, lexerRule, node);
				guard.attached(parent, value);
			}
		};
	}
}
