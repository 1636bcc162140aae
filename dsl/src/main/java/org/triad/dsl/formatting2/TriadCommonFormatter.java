package org.triad.dsl.formatting2;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.formatting2.AbstractFormatter2;
import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormattableDocument;
import org.eclipse.xtext.formatting2.IHiddenRegionFormatter;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;
import org.eclipse.xtext.preferences.MapBasedPreferenceValues;
import org.eclipse.xtext.resource.XtextResource;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.Enumeration;
import org.triad.dsl.triad.SituationObject;

/**
 * The layout of every Triad language, which share one token style (the paper's listings): one
 * statement per line, blocks indented by two spaces inside braces, a blank line between top-level
 * elements, single spaces around operators, none inside calls and parameter lists. A block without
 * nested blocks that the author wrote on one line stays on one line if it holds values ({@code enum E { A, B; }},
 * {@code class C { String name; }}, {@code Room r { name = "R"; };}); single blank lines inside blocks are kept
 * (but not a blank line between two consecutive line comments: Xtext's comment replacer joins them).
 */
public class TriadCommonFormatter extends AbstractFormatter2 {
	private static final Set<String> TIGHT_BEFORE = Set.of(";", ",", ")", ".", ":", "@pre");
	private static final Set<String> TIGHT_AFTER = Set.of("(", ".", "!");
	/** The house indentation; Xtext's default (a tab) counts as "not chosen by the editor". */
	private static final String INDENTATION = "  ";

	@Override
	protected void initialize(FormatterRequest request) {
		if ("\t".equals(request.getPreferences().getPreference(FormatterPreferenceKeys.indentation))) {
			request.setPreferences(new MapBasedPreferenceValues(request.getPreferences(),
					Map.of(FormatterPreferenceKeys.indentation.getId(), INDENTATION)));
		}
		super.initialize(request);
	}

	@Override
	public void format(Object obj, IFormattableDocument document) {
		if (getTextRegionAccess().hasSyntaxError()) {
			// a model that does not parse has no reliable token structure: leave its text as it is
			return;
		}
		if (obj instanceof XtextResource resource) {
			// the formatter is entered with the resource, not its root
			for (EObject root : List.copyOf(resource.getContents())) {
				format(root, document);
			}
			return;
		}
		if (!(obj instanceof EObject root) || root.eContainer() != null) {
			return;
		}
		List<ISemanticRegion> tokens = new ArrayList<>();
		getTextRegionAccess().regionForEObject(root).getAllSemanticRegions().forEach(tokens::add);
		Set<ISemanticRegion> inlineOpen = inlineBlocks(tokens);
		Deque<ISemanticRegion> openBraces = new ArrayDeque<>();
		for (int i = 0; i < tokens.size(); i++) {
			ISemanticRegion token = tokens.get(i);
			String text = keyword(token);
			if ("{".equals(text)) {
				openBraces.push(token);
			} else if ("}".equals(text) && !openBraces.isEmpty()) {
				ISemanticRegion open = openBraces.pop();
				if (!inlineOpen.contains(open)) {
					document.interior(open, token, IHiddenRegionFormatter::indent);
				}
			}
			if (i + 1 < tokens.size()) {
				boolean inline = !openBraces.isEmpty() && inlineOpen.contains(openBraces.peek())
						|| "}".equals(keyword(tokens.get(i + 1))) && inlineOpen.contains(matchingOpen(tokens, i + 1));
				layoutBetween(token, text, tokens.get(i + 1), openBraces.size(), inline, document);
			}
		}
	}

	/** The opening braces of blocks that contain no block and were written on one line. */
	private Set<ISemanticRegion> inlineBlocks(List<ISemanticRegion> tokens) {
		Set<ISemanticRegion> result = new HashSet<>();
		Deque<Integer> open = new ArrayDeque<>();
		Deque<Boolean> hasNested = new ArrayDeque<>();
		for (int i = 0; i < tokens.size(); i++) {
			String text = keyword(tokens.get(i));
			if ("{".equals(text)) {
				if (!hasNested.isEmpty()) {
					hasNested.pop();
					hasNested.push(true);
				}
				open.push(i);
				hasNested.push(false);
			} else if ("}".equals(text) && !open.isEmpty()) {
				ISemanticRegion first = tokens.get(open.pop());
				boolean nested = hasNested.pop();
				ISemanticRegion last = tokens.get(i);
				String inside = getTextRegionAccess().textForOffset(first.getEndOffset(), last.getOffset() - first.getEndOffset());
				if (!nested && inside.indexOf('\n') < 0 && isDataBlock(first.getSemanticElement())) {
					result.add(first);
				}
			}
		}
		return result;
	}

	/** Blocks of values, which read well on one line; behaviour (actors, actions, goals, tasks, states) never is. */
	private static boolean isDataBlock(EObject owner) {
		return owner instanceof DomainClass || owner instanceof Enumeration || owner instanceof SituationObject;
	}

	private static ISemanticRegion matchingOpen(List<ISemanticRegion> tokens, int close) {
		int depth = 0;
		for (int i = close; i >= 0; i--) {
			String text = keyword(tokens.get(i));
			if ("}".equals(text)) {
				depth++;
			} else if ("{".equals(text) && --depth == 0) {
				return tokens.get(i);
			}
		}
		return null;
	}

	private void layoutBetween(ISemanticRegion prev, String prevKw, ISemanticRegion next, int depth, boolean inline,
			IFormattableDocument document) {
		String nextKw = keyword(next);
		if (inline && ("}".equals(nextKw) || "{".equals(prevKw))) {
			document.append(prev, f -> f.oneSpace());
		} else if ("}".equals(nextKw) || "{".equals(prevKw)) {
			document.append(prev, f -> f.newLine());
		} else if (nextKw != null && TIGHT_BEFORE.contains(nextKw) || prevKw != null && TIGHT_AFTER.contains(prevKw)
				|| "-".equals(prevKw) && prev.getSemanticElement() instanceof org.triad.dsl.triad.NegationExpression) {
			document.append(prev, f -> f.noSpace());
		} else if ("(".equals(nextKw)) {
			document.append(prev, prevKw == null ? f -> f.noSpace() : f -> f.oneSpace());
		} else if (inline) {
			document.append(prev, f -> f.oneSpace());
		} else if (";".equals(prevKw) || "}".equals(prevKw)) {
			if (depth == 0) {
				document.append(prev, f -> f.setNewLines(2));
			} else {
				document.append(prev, f -> f.setNewLines(1, 1, 2));
			}
		} else {
			document.append(prev, f -> f.oneSpace());
		}
	}

	/** The keyword a token is, or null for names and literals. */
	private static String keyword(ISemanticRegion region) {
		return region.getGrammarElement() instanceof Keyword k ? k.getValue() : null;
	}
}
