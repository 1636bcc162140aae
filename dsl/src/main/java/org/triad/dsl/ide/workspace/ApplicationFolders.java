package org.triad.dsl.ide.workspace;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;

/**
 * Which application a model file belongs to when an editor opens a folder holding several (the
 * repository root holds models/hospital and models/logistics): the files below the deepest folder
 * that holds both the file and a class diagram, the way {@code triad check DIR} takes the models
 * below one folder as one application. Architecture files are not sliced: they refer to
 * components across modules.
 */
public final class ApplicationFolders {
	private ApplicationFolders() {
	}

	/** The application folder of {@code file} as a URI prefix ending in '/', or null for "the whole workspace". */
	public static String root(URI file, IResourceDescriptions index) {
		if (file == null || index == null || "arc".equals(file.fileExtension())) {
			return null;
		}
		String dir = folder(file);
		String best = null;
		for (IResourceDescription d : index.getAllResourceDescriptions()) {
			if ("cd".equals(d.getURI().fileExtension())) {
				String common = commonFolder(dir, folder(d.getURI()));
				if (best == null || common.length() > best.length()) {
					best = common;
				}
			}
		}
		return best == null || best.isEmpty() ? null : best;
	}

	/** Whether {@code uri} lies below the folder {@code root} (a prefix from {@link #root}). */
	public static boolean contains(String root, URI uri) {
		return root == null || uri != null && uri.toString().startsWith(root);
	}

	private static String folder(URI file) {
		String s = file.toString();
		return s.substring(0, s.lastIndexOf('/') + 1);
	}

	private static String commonFolder(String a, String b) {
		int n = Math.min(a.length(), b.length());
		int i = 0;
		while (i < n && a.charAt(i) == b.charAt(i)) {
			i++;
		}
		return a.substring(0, a.lastIndexOf('/', Math.max(0, i - 1)) + 1);
	}
}
