package org.triad.dsl.linking;

import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.triad.dsl.parser.ExpressionTooDeepException;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * Syntax errors carry the stable code {@value CommonIssueCodes#SYNTAX}; an expression past the depth
 * limits {@value CommonIssueCodes#EXPRESSION_TOO_DEEP}.
 */
public class TriadSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {
	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
		if (context.getRecognitionException() instanceof ExpressionTooDeepException tooDeep) {
			return new SyntaxErrorMessage(tooDeep.reason() + "; split it into smaller goals, conditions or facts",
					CommonIssueCodes.EXPRESSION_TOO_DEEP);
		}
		return new SyntaxErrorMessage(super.getSyntaxErrorMessage(context).getMessage(), CommonIssueCodes.SYNTAX);
	}

	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IValueConverterErrorContext context) {
		return new SyntaxErrorMessage(super.getSyntaxErrorMessage(context).getMessage(), CommonIssueCodes.SYNTAX);
	}
}
