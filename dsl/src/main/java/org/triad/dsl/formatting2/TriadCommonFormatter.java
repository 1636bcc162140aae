package org.triad.dsl.formatting2;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.formatting2.AbstractFormatter2;
import org.eclipse.xtext.formatting2.IFormattableDocument;
import org.eclipse.xtext.formatting2.IHiddenRegionFormatter;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;

/**
 * The layout of every Triad language, which share one token style: one statement per line, blocks
 * indented inside braces, a blank line between top-level elements, single spaces around operators,
 * none inside calls and parameter lists.
 */
public class TriadCommonFormatter extends AbstractFormatter2 {
	private static final Set<String> TIGHT_BEFORE = Set.of(";", ",", ")", ".", ":");
	private static final Set<String> TIGHT_AFTER = Set.of("(", ".", "!");

	@Override
	public void format(Object obj, IFormattableDocument document) {
		if (!(obj instanceof EObject root) || root.eContainer() != null) {
			return;
		}
		List<ISemanticRegion> tokens = new java.util.ArrayList<>();
		getTextRegionAccess().regionForEObject(root).getAllSemanticRegions().forEach(tokens::add);
		Deque<ISemanticRegion> openBraces = new ArrayDeque<>();
		for (int i = 0; i < tokens.size(); i++) {
			ISemanticRegion token = tokens.get(i);
			String text = keyword(token);
			if ("{".equals(text)) {
				openBraces.push(token);
			} else if ("}".equals(text) && !openBraces.isEmpty()) {
				document.interior(openBraces.pop(), token, IHiddenRegionFormatter::indent);
			}
			if (i + 1 < tokens.size()) {
				layoutBetween(token, text, tokens.get(i + 1), openBraces.size(), document);
			}
		}
	}

	private void layoutBetween(ISemanticRegion prev, String prevKw, ISemanticRegion next, int depth, IFormattableDocument document) {
		String nextKw = keyword(next);
		if ("}".equals(nextKw) || "{".equals(prevKw)) {
			document.append(prev, f -> f.newLine());
		} else if (nextKw != null && TIGHT_BEFORE.contains(nextKw) || prevKw != null && TIGHT_AFTER.contains(prevKw)) {
			document.append(prev, f -> f.noSpace());
		} else if ("(".equals(nextKw)) {
			document.append(prev, prevKw == null ? f -> f.noSpace() : f -> f.oneSpace());
		} else if (";".equals(prevKw) || "}".equals(prevKw)) {
			int lines = depth == 0 ? 2 : 1;
			document.append(prev, f -> f.setNewLines(lines));
		} else {
			document.append(prev, f -> f.oneSpace());
		}
	}

	/** The keyword a token is, or null for names and literals. */
	private static String keyword(ISemanticRegion region) {
		return region.getGrammarElement() instanceof Keyword k ? k.getValue() : null;
	}
}
