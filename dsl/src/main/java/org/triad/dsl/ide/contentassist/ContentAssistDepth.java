package org.triad.dsl.ide.contentassist;

import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.triad.dsl.parser.ExpressionLimits;

/**
 * Whether a text nests too deep for the content-assist parser, which (unlike the model parser, see
 * {@link org.triad.dsl.parser.ExpressionDepthGuard}) recurses per level without a guard: past this,
 * completion offers nothing instead of overflowing the stack. The model parser already reports such
 * a text as {@code expr.too-deep}, so nothing there could be completed sensibly anyway.
 */
final class ContentAssistDepth {
	/** Far past {@link ExpressionLimits#MAX_NESTING}, far below what overflows a 1 MB thread stack. */
	static final int MAX_LEVELS = 3 * ExpressionLimits.MAX_NESTING;

	private ContentAssistDepth() {
	}

	static boolean tooDeep(TokenStream tokens) {
		int open = 0;
		int negations = 0;
		for (int i = 0; i < tokens.size(); i++) {
			Token t = tokens.get(i);
			if (t.getChannel() != Token.DEFAULT_CHANNEL) {
				continue;
			}
			String text = t.getText();
			if ("(".equals(text)) {
				open++;
			} else if (")".equals(text)) {
				open = Math.max(0, open - 1);
			}
			negations = "!".equals(text) ? negations + 1 : 0;
			if (open + negations > MAX_LEVELS) {
				return true;
			}
		}
		return false;
	}
}
