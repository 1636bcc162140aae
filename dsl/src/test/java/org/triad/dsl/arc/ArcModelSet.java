package org.triad.dsl.arc;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;
import org.triad.dsl.TriadLanguages;

/** Test fixture: .arc files given as text, loaded into one resource set so they link to each other. */
final class ArcModelSet {
	/** One diagnostic as a test compares it: file, line, code. */
	record Found(String file, int line, String code, String message, boolean error) {
		@Override
		public String toString() {
			return file + ":" + line + ": " + code + ": " + message;
		}
	}

	private final XtextResourceSet resourceSet;
	private final List<Resource> resources = new ArrayList<>();

	private ArcModelSet(Map<String, String> files) {
		resourceSet = TriadLanguages.setup().get("arc").getInstance(XtextResourceSet.class);
		files.forEach((name, text) -> {
			Resource r = resourceSet.createResource(URI.createURI("memory:/models/" + name));
			try {
				r.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of());
			} catch (IOException e) {
				throw new UncheckedIOException(e);
			}
			resources.add(r);
		});
		EcoreUtil.resolveAll(resourceSet);
	}

	static ArcModelSet of(Map<String, String> files) {
		return new ArcModelSet(files);
	}

	static ArcModelSet of(String name, String text) {
		return new ArcModelSet(Map.of(name, text));
	}

	XtextResourceSet resourceSet() {
		return resourceSet;
	}

	ArcModel model(String name) {
		for (Resource r : resources) {
			if (r.getURI().lastSegment().equals(name)) {
				return (ArcModel) r.getContents().get(0);
			}
		}
		throw new IllegalArgumentException("no file " + name);
	}

	List<Found> issues() {
		List<Found> found = new ArrayList<>();
		for (Resource r : resources) {
			XtextResource x = (XtextResource) r;
			for (Issue i : x.getResourceServiceProvider().getResourceValidator().validate(r, CheckMode.ALL, CancelIndicator.NullImpl)) {
				found.add(new Found(r.getURI().lastSegment(), i.getLineNumber() == null ? 0 : i.getLineNumber(), i.getCode(), i.getMessage(),
						i.getSeverity() == org.eclipse.xtext.diagnostics.Severity.ERROR));
			}
		}
		return found;
	}
}
