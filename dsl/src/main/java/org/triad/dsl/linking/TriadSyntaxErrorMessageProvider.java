package org.triad.dsl.linking;

import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.triad.dsl.parser.ExpressionTooDeepException;
import org.triad.dsl.validation.CommonIssueCodes;

/**
 * Syntax errors carry the stable code {@value CommonIssueCodes#SYNTAX}; an expression past the depth
 * limits {@value CommonIssueCodes#EXPRESSION_TOO_DEEP}, an int literal too large for an int {@value CommonIssueCodes#OVERFLOW}.
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
		org.eclipse.xtext.conversion.ValueConverterException e = context.getValueConverterException();
		String text = e == null || e.getNode() == null ? null : e.getNode().getText().strip();
		if (e != null && e.getCause() instanceof NumberFormatException && text != null && text.matches("[0-9]+")) {
			// an int literal past Integer.MAX_VALUE: the converter's message ("For input string") names no cause
			return new SyntaxErrorMessage("'" + text + "' is too large for an int (at most 2147483647; write a decimal such as " + text
					+ ".0 for a double)", CommonIssueCodes.OVERFLOW);
		}
		return new SyntaxErrorMessage(super.getSyntaxErrorMessage(context).getMessage(), CommonIssueCodes.SYNTAX);
	}
}
