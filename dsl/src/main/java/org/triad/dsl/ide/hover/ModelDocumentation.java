package org.triad.dsl.ide.hover;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;

/**
 * An element's documentation: the comment written directly above its declaration, either a run of
 * {@code //} lines or one {@code /* ... *}{@code /} block, with no blank line in between. Model
 * authors document actors, goals and tasks this way (see models/hospital), so both forms count.
 */
public class ModelDocumentation implements IEObjectDocumentationProvider {
	@Override
	public String getDocumentation(EObject element) {
		ICompositeNode node = NodeModelUtils.findActualNodeFor(element);
		if (node == null) {
			return null;
		}
		String text = node.getRootNode().getText();
		int start = node.getOffset();
		int lineStart = text.lastIndexOf('\n', start - 1) + 1;
		if (!text.substring(lineStart, start).isBlank()) {
			return null; // declared mid-line (e.g. a parameter): nothing above belongs to it
		}
		List<String> lines = new ArrayList<>(List.of(text.substring(0, lineStart).split("\n", -1)));
		lines.remove(lines.size() - 1); // the empty piece after the last newline
		return commentAbove(lines);
	}

	static String commentAbove(List<String> linesAbove) {
		List<String> doc = new ArrayList<>();
		int i = linesAbove.size() - 1;
		if (i >= 0 && linesAbove.get(i).strip().endsWith("*/")) {
			while (i >= 0) {
				String line = linesAbove.get(i).strip();
				int open = line.indexOf("/*");
				doc.add(clean(open >= 0 ? line.substring(open + 2) : line));
				if (open >= 0) {
					break;
				}
				i--;
			}
			if (i < 0) {
				return null;
			}
		} else {
			while (i >= 0 && linesAbove.get(i).strip().startsWith("//")) {
				doc.add(linesAbove.get(i).strip().substring(2).strip());
				i--;
			}
		}
		Collections.reverse(doc);
		while (!doc.isEmpty() && doc.get(0).isEmpty()) {
			doc.remove(0);
		}
		while (!doc.isEmpty() && doc.get(doc.size() - 1).isEmpty()) {
			doc.remove(doc.size() - 1);
		}
		return doc.isEmpty() ? null : String.join("\n", doc);
	}

	private static String clean(String blockLine) {
		String s = blockLine.strip();
		if (s.endsWith("*/")) {
			s = s.substring(0, s.length() - 2).strip();
		}
		while (s.startsWith("*")) {
			s = s.substring(1).strip();
		}
		return s;
	}
}
