package org.triad.dsl.ide.hover;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.xtext.ide.server.hover.HoverContext;
import org.eclipse.xtext.ide.server.hover.HoverService;

import com.google.inject.Inject;

/**
 * Hover on a name (a reference or a declaration): the element's declaration in its model's own
 * syntax, then its documentation comment.
 */
public class TriadHoverService extends HoverService {
	@Inject
	private ModelDocumentation documentation;

	@Override
	public String getContents(EObject element) {
		String signature = element == null ? null : ModelSignatures.of(element);
		if (signature == null) {
			return "";
		}
		StringBuilder b = new StringBuilder("```").append(languageId(element)).append('\n').append(signature).append("\n```");
		String doc = documentation.getDocumentation(element);
		if (doc != null) {
			b.append("\n\n").append(doc);
		}
		return b.toString();
	}

	/** Nothing to show is no hover at all, rather than an empty one. */
	@Override
	protected MarkupContent getMarkupContent(HoverContext context) {
		String contents = getContents(context.getElement());
		return contents.isEmpty() ? null : toMarkupContent(getKind(context), contents);
	}

	/** The editor language id of the element's file (triad-goal, ...), so fenced code is coloured. */
	static String languageId(EObject element) {
		Resource r = element.eResource();
		String ext = r == null || r.getURI() == null ? null : r.getURI().fileExtension();
		return ext == null ? "" : "triad-" + ext;
	}
}
