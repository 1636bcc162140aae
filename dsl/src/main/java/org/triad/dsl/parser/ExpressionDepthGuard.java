package org.triad.dsl.parser;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;

import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.ParserRule;
import org.eclipse.xtext.RuleCall;
import org.triad.dsl.triad.Expression;

/**
 * Keeps one parse of a Triad model inside the {@link ExpressionLimits}. The generated parser reports
 * every rule call ({@code newCompositeNode}), every return from one and every tree-building action
 * to it; past a limit it throws {@link ExpressionTooDeepException} inside the current rule, whose
 * error recovery then skips the rest of the too-deep part like any syntax error.
 * <p>
 * Nesting counts calls of the rule {@code Expression} from inside an expression (parentheses, call
 * arguments), of {@code Not} from {@code Not} (each {@code !} after the first) and of {@code Unary} from {@code Unary}
 * (each {@code -} after the first). Operator chains
 * are measured as the height of the tree built so far, which the actions
 * {@code {BinaryExpression.left=current}} extend by one on top of their left operand.
 */
final class ExpressionDepthGuard {
	private static final Set<String> END = Set.of(")", ",", ";", "}");

	private final TokenStream input;
	private final Deque<Boolean> calls = new ArrayDeque<>();
	private final Map<EObject, Integer> heights = new IdentityHashMap<>();
	/** Per rule call of the grammar: the nesting caller's name, or "" when the call does not nest. */
	private final Map<EObject, String> callers = new IdentityHashMap<>();
	private int nesting;

	ExpressionDepthGuard(TokenStream input) {
		this.input = input;
	}

	/** Before the generated parser enters a rule; throws instead when that would nest too deep. */
	void enteringRule(EObject grammarElement) {
		String caller = callers.computeIfAbsent(grammarElement, ExpressionDepthGuard::nestingCaller);
		boolean nests = !caller.isEmpty();
		if (nests && nesting >= ExpressionLimits.MAX_NESTING) {
			ExpressionTooDeepException tooDeep = new ExpressionTooDeepException(input, "the expression nests more than "
					+ ExpressionLimits.MAX_NESTING + " levels of parentheses, negations and call arguments");
			// a parenthesis or call that gives up never matches its closing parenthesis: it goes with the skipped part
			skipRestOfExpression(!caller.equals("Not") && !caller.equals("Unary"));
			throw ExpressionDepthGuard.<RuntimeException>unchecked(tooDeep);
		}
		calls.push(nests);
		if (nests) {
			nesting++;
		}
	}

	/** After the generated parser returned from a rule entered through {@link #enteringRule}. */
	void leftRule() {
		if (!calls.isEmpty() && calls.pop()) {
			nesting--;
		}
	}

	/** Before an action puts {@code left} below a new operator; throws instead when the chain gets too long. */
	void stacking(EObject left) {
		if (height(left) > ExpressionLimits.MAX_DEPTH) { // a leaf has height 1: the new operator would be one too many
			ExpressionTooDeepException tooDeep = new ExpressionTooDeepException(input, "the expression is more than "
					+ ExpressionLimits.MAX_DEPTH + " operators deep (each operator of a chain such as a && b && c is one level)");
			skipRestOfExpression(false);
			throw ExpressionDepthGuard.<RuntimeException>unchecked(tooDeep);
		}
	}

	/** After an action or an assignment made {@code child} an operand of {@code parent}. */
	void attached(EObject parent, Object child) {
		if (parent instanceof Expression && child instanceof Expression e) {
			heights.merge(parent, height(e) + 1, Math::max);
		}
	}

	/**
	 * The generated rules catch {@link org.antlr.runtime.RecognitionException}, a checked exception,
	 * but the parser's hooks that see the depth do not declare it; it is thrown past the compiler.
	 */
	@SuppressWarnings("unchecked")
	private static <T extends Throwable> T unchecked(Throwable t) throws T {
		throw (T) t;
	}

	private int height(EObject e) {
		return heights.getOrDefault(e, 1);
	}

	/** The rule that calls a nested expression, or "" when the call does not nest one. */
	private static String nestingCaller(EObject grammarElement) {
		if (grammarElement instanceof RuleCall call && call.getRule() instanceof ParserRule rule) {
			String caller = GrammarUtil.containingRule(call).getName();
			boolean nests = switch (rule.getName()) {
				case "Expression" -> caller.equals("Primary") || caller.equals("Reference");
				case "Not" -> caller.equals("Not");
				case "Unary" -> caller.equals("Unary"); // - - - x: each '-' after the first, as '!'
				default -> false;
			};
			return nests ? caller : "";
		}
		return "";
	}

	/**
	 * Skips the rest of the too-deep expression: to the parenthesis, comma, semicolon or brace that
	 * ends it, outside any parentheses it opens, or past the parenthesis that closes the call or
	 * parentheses whose rule gives up. The enclosing rule then goes on after it, so the
	 * too-deep part is one error, not one per parenthesis or operator that follows.
	 */
	private void skipRestOfExpression(boolean withClosingParenthesis) {
		int open = 0;
		while (input.LA(1) != Token.EOF) {
			String text = input.LT(1).getText();
			if (open == 0 && withClosingParenthesis && ")".equals(text)) {
				input.consume();
				return;
			}
			if (open == 0 && !withClosingParenthesis && END.contains(text)) {
				return;
			}
			if ("(".equals(text)) {
				open++;
			} else if (")".equals(text)) {
				open--;
			}
			input.consume();
		}
	}
}
